//! Resolution of `$name` parameter references and `${…}` expressions in attribute values
//! (OpenSCENARIO 1.3 §9.1 "Parameters", §9.2 "Expressions"): the innermost declaration in
//! scope wins; expressions go to [`crate::expr::evaluate`]; errors point at the attribute
//! value, and inside an expression at the offending token.

use std::cell::Cell;

use roxmltree::Attribute;

use crate::attr::FromAttr;
use crate::error::{Error, ErrorKind, Result};
use crate::expr::{self, Value};
use crate::reader::context::{Ctx, Node};
use crate::warning::Warning;

impl<'a> Ctx<'a> {
    /// The value of parameter `name` in the innermost scope that declares it.
    pub fn lookup(&self, name: &str) -> Option<Value> {
        let name = name.strip_prefix('$').unwrap_or(name);
        self.scopes
            .iter()
            .rev()
            .flat_map(|s| s.params.iter().rev())
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.clone())
    }

    /// Resolves `$name` and `${expr}` in the raw text of attribute `a` of element `n`.
    pub fn resolve(&self, n: Node<'a>, a: &Attribute<'a, 'a>) -> Result<String> {
        let raw = a.value();
        let trimmed = raw.trim_start();
        let lead = raw.len() - trimmed.len();
        let trimmed = trimmed.trim_end();
        let attribute = || format!("{}@{}", n.tag_name().name(), a.name());
        if let Some(inner) = trimmed.strip_prefix("${").and_then(|s| s.strip_suffix('}')) {
            let numeric_string = Cell::new(false);
            let lookup = |name: &str| match self.lookup(name) {
                // The grammar has no operator on strings but comparison; a string parameter
                // holding a number (esmini's habit) is offered as that number, with a warning.
                Some(Value::String(s)) if f64::from_attr(&s).is_some() => {
                    numeric_string.set(true);
                    f64::from_attr(&s).map(|(d, _)| Value::Double(d))
                }
                other => other,
            };
            let source = crate::reader::compat::esmini_constants(inner);
            let result = expr::evaluate(&source, &lookup)
                .map(|v| v.to_string())
                .map_err(|e| {
                    // Offsets hold in the text as written unless `pi` was replaced before them.
                    let offset = if source.len() == inner.len() {
                        e.offset()
                    } else {
                        0
                    };
                    let offset = a.range_value().start + lead + 2 + offset;
                    Error::new(
                        ErrorKind::Expression {
                            attribute: attribute(),
                            message: e.to_string(),
                        },
                        self.pos_at(offset),
                    )
                });
            if numeric_string.get() && result.is_ok() {
                self.warnings_later.borrow_mut().push(Warning {
                    message: format!(
                        "{}: a string parameter holding a number is used as a number",
                        attribute()
                    ),
                    pos: self.attr_pos(a),
                });
            }
            return result;
        }
        if trimmed.starts_with("${") {
            // `${` without its closing `}` at the end of the value.
            return Err(Error::new(
                ErrorKind::Expression {
                    attribute: attribute(),
                    message: "expected '}' at the end of the value, found none".into(),
                },
                self.pos_at(a.range_value().start + lead),
            ));
        }
        if let Some(name) = trimmed.strip_prefix('$') {
            return self.lookup(name).map(|v| v.to_string()).ok_or_else(|| {
                Error::new(
                    ErrorKind::UnknownParameter {
                        name: name.to_owned(),
                        attribute: attribute(),
                    },
                    self.attr_pos(a),
                )
            });
        }
        Ok(raw.to_owned())
    }
}
