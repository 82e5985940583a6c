//! Syntax kinds: every token and node kind of the concrete syntax tree.
//!
//! The token kinds follow the lexical structure of ASAM OpenSCENARIO DSL 2.1 §7.2.1 (keywords
//! table 4, operators and delimiters table 5, literals §7.2.1.5.2); the node kinds follow the
//! productions of §7.2.2 (one node kind per production that carries meaning, named after it).
//!
//! Keywords are *contextual* (§7.2.1.5.1: "only recognized as keywords in the places identified
//! in the grammar"): the lexer produces [`SyntaxKind::IDENT`] for every word, and the parser
//! re-kinds a word to its keyword kind (`STRUCT_KW`, …) only where the grammar asks for that
//! keyword. So `speed: speed` and a field named `event` stay identifiers.

macro_rules! syntax_kinds {
    (
        tokens { $($(#[$tdoc:meta])* $tok:ident),* $(,)? }
        keywords { $($kw:ident = $text:literal),* $(,)? }
        nodes { $($(#[$ndoc:meta])* $node:ident),* $(,)? }
    ) => {
        /// The kind of a token or node of the syntax tree.
        #[allow(non_camel_case_types, missing_docs)]
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[repr(u16)]
        pub enum SyntaxKind {
            $($(#[$tdoc])* $tok,)*
            $($kw,)*
            $($(#[$ndoc])* $node,)*
            /// Not a kind: one past the last one.
            #[doc(hidden)]
            __LAST,
        }

        impl SyntaxKind {
            const ALL: &'static [SyntaxKind] = &[$(SyntaxKind::$tok,)* $(SyntaxKind::$kw,)* $(SyntaxKind::$node,)*];

            /// The keyword kind spelled `text`, if `text` is one of the language's keywords.
            pub fn from_keyword(text: &str) -> Option<SyntaxKind> {
                match text {
                    $($text => Some(SyntaxKind::$kw),)*
                    _ => None,
                }
            }

            /// Whether this is a keyword kind.
            pub fn is_keyword(self) -> bool {
                matches!(self, $(SyntaxKind::$kw)|*)
            }

            /// The keyword's spelling, for keyword kinds.
            pub fn keyword_text(self) -> Option<&'static str> {
                match self {
                    $(SyntaxKind::$kw => Some($text),)*
                    _ => None,
                }
            }
        }
    };
}

syntax_kinds! {
    tokens {
        // Trivia: kept in the tree, ignored by the grammar.
        WHITESPACE, COMMENT, LINE_BREAK, LINE_CONTINUATION,
        // Layout (§7.2.1.2, §7.2.1.4). INDENT and DEDENT are zero-width.
        NEWLINE, INDENT, DEDENT,
        // Words and literals (§7.2.1.5).
        IDENT, INT_NUMBER, FLOAT_NUMBER, UNIT, STRING,
        // Operators and delimiters (table 5, plus `..`, `::`, `!`).
        DOT, DOT2, COMMA, COLON, COLON2, EQ, AT, ARROW, FAT_ARROW, L_PAREN, R_PAREN, L_BRACK,
        R_BRACK, QUESTION, EQ2, NEQ, LT, LTEQ, GT, GTEQ, PLUS, MINUS, STAR, SLASH, PERCENT, BANG,
        /// A character that starts no token, or an unterminated string or quoted identifier.
        ERROR_TOKEN,
    }
    keywords {
        ACTION_KW = "action", ACTOR_KW = "actor", AND_KW = "and", AS_KW = "as", BOOL_KW = "bool",
        CALL_KW = "call", COVER_KW = "cover", DEF_KW = "def", DEFAULT_KW = "default", DO_KW = "do",
        ELAPSED_KW = "elapsed", EMIT_KW = "emit", ENUM_KW = "enum", EVENT_KW = "event",
        EVERY_KW = "every", EXPORT_KW = "export", EXPRESSION_KW = "expression",
        EXTEND_KW = "extend", EXTERNAL_KW = "external", FACTOR_KW = "factor", FALL_KW = "fall",
        FALSE_KW = "false", FLOAT_KW = "float", FOR_KW = "for", GLOBAL_KW = "global",
        HARD_KW = "hard", IF_KW = "if", IMPORT_KW = "import", IN_KW = "in", INF_KW = "inf",
        INHERITS_KW = "inherits", INT_KW = "int", IS_KW = "is", IT_KW = "it", KEEP_KW = "keep",
        LIST_KW = "list", MODIFIER_KW = "modifier", NAMESPACE_KW = "namespace", NAN_KW = "nan",
        NOT_KW = "not", NULL_KW = "null", OF_KW = "of", OFFSET_KW = "offset", ON_KW = "on",
        ONE_OF_KW = "one_of", ONLY_KW = "only", OR_KW = "or", PARALLEL_KW = "parallel",
        RANGE_KW = "range", RECORD_KW = "record", REMOVE_DEFAULT_KW = "remove_default",
        RISE_KW = "rise", SAMPLE_KW = "sample", SCENARIO_KW = "scenario", SERIAL_KW = "serial",
        SI_KW = "SI", STRING_KW = "string", STRUCT_KW = "struct", TRUE_KW = "true",
        TYPE_KW = "type", UINT_KW = "uint", UNDEFINED_KW = "undefined", UNIT_KW = "unit",
        UNTIL_KW = "until", USE_KW = "use", VAR_KW = "var", WAIT_KW = "wait", WITH_KW = "with",
    }
    nodes {
        // §7.2.2.1 top level
        SOURCE_FILE, IMPORT_STMT, NAMESPACE_STMT, EXPORT_STMT, EXPORT_SPEC,
        // names
        NAME, NAME_REF, BEHAVIOR_NAME,
        // §7.2.2.2 types
        PHYSICAL_TYPE_DECL, UNIT_DECL, SI_SPEC, SI_ARG, ENUM_DECL, ENUM_MEMBER_LIST, ENUM_MEMBER,
        ENUM_EXTENSION, STRUCT_DECL, ACTOR_DECL, SCENARIO_DECL, ACTION_DECL, MODIFIER_DECL,
        EXTEND_DECL, INHERITS, INHERITS_CONDITION,
        /// `NEWLINE INDENT member+ DEDENT` after a `:`.
        BLOCK,
        PRIMITIVE_TYPE, NAMED_TYPE, LIST_TYPE, RANGE_TYPE,
        // §7.2.2.3 global parameters
        GLOBAL_PARAM_DECL,
        // §7.2.2.4 members
        EVENT_DECL, PARAM_DECL, VAR_DECL, FIELD_NAMES, PARAM_WITH, KEEP_CONSTRAINT,
        REMOVE_DEFAULT, METHOD_DECL, RETURN_TYPE, METHOD_BODY, COVERAGE_DECL,
        MODIFIER_APPLICATION, ON_DIRECTIVE, DO_DIRECTIVE, LABEL, COMPOSITION,
        BEHAVIOR_INVOCATION, BEHAVIOR_WITH, WAIT_DIRECTIVE,
        EMIT_DIRECTIVE, CALL_DIRECTIVE, UNTIL_DIRECTIVE,
        /// `for v in g.vehicles:` constraint loop (the domain model's vehicle_group example).
        FOR_CONSTRAINT,
        // events
        EVENT_SPEC, EVENT_REF, EVENT_FIELD, RISE_EXPR, FALL_EXPR, ELAPSED_EXPR, EVERY_EXPR,
        SAMPLE_EXPR,
        // §7.2.2.5 arguments
        PARAM_LIST, PARAM, ARG_LIST, ARG, NAMED_ARG,
        // §7.2.2.6 expressions
        LITERAL, LIST_EXPR, RANGE_EXPR, PAREN_EXPR, NAME_EXPR, IT_EXPR, ENUM_VALUE_EXPR,
        BIN_EXPR, PREFIX_EXPR, TERNARY_EXPR, FIELD_EXPR, INDEX_EXPR, CALL_EXPR, CAST_EXPR,
        TYPE_TEST_EXPR,
        /// Tokens the parser could not place; a diagnostic says why.
        ERROR,
    }
}

use SyntaxKind::*;

impl SyntaxKind {
    /// Whether tokens of this kind are ignored by the grammar (whitespace, comments, line
    /// breaks inside brackets or in blank lines, `\` line continuations).
    pub fn is_trivia(self) -> bool {
        matches!(self, WHITESPACE | COMMENT | LINE_BREAK | LINE_CONTINUATION)
    }

    /// Whether this is a token kind (as opposed to a node kind).
    pub fn is_token(self) -> bool {
        (self as u16) <= (WITH_KW as u16)
    }

    /// How the kind is named in diagnostics: the keyword or punctuation in backquotes, or a
    /// description of the token class.
    pub fn describe(self) -> &'static str {
        if let Some(text) = self.keyword_text() {
            return text;
        }
        match self {
            WHITESPACE => "whitespace",
            COMMENT => "comment",
            LINE_BREAK | NEWLINE => "end of line",
            LINE_CONTINUATION => "line continuation",
            INDENT => "indented block",
            DEDENT => "end of block",
            IDENT => "identifier",
            INT_NUMBER => "integer",
            FLOAT_NUMBER => "number",
            UNIT => "unit",
            STRING => "string",
            DOT => "`.`",
            DOT2 => "`..`",
            COMMA => "`,`",
            COLON => "`:`",
            COLON2 => "`::`",
            EQ => "`=`",
            AT => "`@`",
            ARROW => "`->`",
            FAT_ARROW => "`=>`",
            L_PAREN => "`(`",
            R_PAREN => "`)`",
            L_BRACK => "`[`",
            R_BRACK => "`]`",
            QUESTION => "`?`",
            EQ2 => "`==`",
            NEQ => "`!=`",
            LT => "`<`",
            LTEQ => "`<=`",
            GT => "`>`",
            GTEQ => "`>=`",
            PLUS => "`+`",
            MINUS => "`-`",
            STAR => "`*`",
            SLASH => "`/`",
            PERCENT => "`%`",
            BANG => "`!`",
            ERROR_TOKEN => "invalid token",
            _ => "syntax node",
        }
    }

    /// Converts a raw rowan kind back; kinds out of range (never produced by this crate's
    /// trees) map to [`SyntaxKind::ERROR`].
    pub fn from_raw(raw: u16) -> SyntaxKind {
        SyntaxKind::ALL.get(raw as usize).copied().unwrap_or(ERROR)
    }
}

impl From<SyntaxKind> for rowan::SyntaxKind {
    fn from(kind: SyntaxKind) -> Self {
        rowan::SyntaxKind(kind as u16)
    }
}

/// The rowan language tag of the OpenSCENARIO DSL.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum OscLanguage {}

impl rowan::Language for OscLanguage {
    type Kind = SyntaxKind;
    fn kind_from_raw(raw: rowan::SyntaxKind) -> SyntaxKind {
        SyntaxKind::from_raw(raw.0)
    }
    fn kind_to_raw(kind: SyntaxKind) -> rowan::SyntaxKind {
        kind.into()
    }
}

/// A node of the concrete syntax tree (rowan red node: has a parent and an absolute offset).
pub type SyntaxNode = rowan::SyntaxNode<OscLanguage>;
/// A token (leaf) of the concrete syntax tree.
pub type SyntaxToken = rowan::SyntaxToken<OscLanguage>;
/// A node or a token.
pub type SyntaxElement = rowan::SyntaxElement<OscLanguage>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn raw_kinds_round_trip() {
        for (i, kind) in SyntaxKind::ALL.iter().enumerate() {
            assert_eq!(*kind as usize, i);
            assert_eq!(SyntaxKind::from_raw(i as u16), *kind);
        }
        assert_eq!(SyntaxKind::from_keyword("one_of"), Some(ONE_OF_KW));
        assert_eq!(SyntaxKind::from_keyword("speed"), None);
        assert!(ONE_OF_KW.is_token() && COMMA.is_token() && !BIN_EXPR.is_token());
    }
}
