//! OpenSCENARIO 1.3 §9.2 "Expressions": the `${…}` language, in layers.
//!
//! | module | job |
//! | --- | --- |
//! | `lexer` | text → tokens, with byte offsets |
//! | `parser` | tokens → syntax tree (recursive descent, depth-bounded) |
//! | `arith` | the operators `+ - * / %`, comparisons, `not and or`, and their type rules |
//! | `function` | the standard's built-in operators written as calls (`round`, `pow`, …) |
//! | `eval` | syntax tree → typed [`Value`], with the standard's type rules |
//! | `value` | [`Value`] and its conversions to a [`ValueType`] |
//! | `value_type` | [`ValueType`]: the XSD parameter types |
//! | `error` | [`ExprError`] and its [`ExprErrorKind`] |
//!
//! Written by hand: the crates that evaluate infix expressions (evalexpr, meval, …) either
//! have the wrong licence (evalexpr is AGPL from v12) or the wrong semantics for this grammar
//! (integer division, `&&`/`||` instead of `and`/`or`, no typed results, no byte offsets).

mod arith;
mod error;
mod eval;
mod function;
mod lexer;
mod parser;
mod value;
mod value_type;

pub use error::{ExprError, ExprErrorKind};
pub use eval::{evaluate, expression_source, Expression};
pub use function::Function;
pub use parser::MAX_DEPTH;
pub use value::Value;
pub use value_type::ValueType;
