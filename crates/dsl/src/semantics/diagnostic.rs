//! Semantic diagnostics: what went wrong, where (a span), and related places (the other
//! constraint of a conflict, the first declaration of a duplicate). `check::Diagnostics`
//! renders them as "MESSAGE at FILE:LINE:COL" lines or as miette reports with snippets.

use super::hir::Span;

/// What kind of semantic error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum DiagnosticKind {
    /// A syntax error reported by the parser.
    Syntax,
    /// An `import` that names no library and no readable file, or an import cycle.
    Import,
    /// A name declared twice in one scope.
    Duplicate,
    /// A name that refers to nothing in scope.
    UnknownName,
    /// Inheritance that names a missing or wrong-kind parent, or a cycle.
    Inheritance,
    /// Operand or argument types that do not fit.
    Type,
    /// Physical dimensions that do not fit (`1m + 1s`) or an unknown unit.
    Units,
    /// Arguments that do not fit a method's or behavior's parameters.
    Arguments,
    /// A modifier applied where it does not apply.
    Modifier,
    /// A constraint form the solver does not handle.
    Unsupported,
    /// Constraints with no solution.
    Unsatisfiable,
    /// A behavior that invokes itself, directly or through others.
    Recursion,
}

impl DiagnosticKind {
    /// A stable code for tools (`osc::type`).
    pub fn code(self) -> &'static str {
        match self {
            DiagnosticKind::Syntax => "osc::syntax",
            DiagnosticKind::Import => "osc::import",
            DiagnosticKind::Duplicate => "osc::duplicate",
            DiagnosticKind::UnknownName => "osc::unknown_name",
            DiagnosticKind::Inheritance => "osc::inheritance",
            DiagnosticKind::Type => "osc::type",
            DiagnosticKind::Units => "osc::units",
            DiagnosticKind::Arguments => "osc::arguments",
            DiagnosticKind::Modifier => "osc::modifier",
            DiagnosticKind::Unsupported => "osc::unsupported",
            DiagnosticKind::Unsatisfiable => "osc::unsatisfiable",
            DiagnosticKind::Recursion => "osc::recursion",
        }
    }
}

/// One semantic error.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// The kind.
    pub kind: DiagnosticKind,
    /// Lowercase message without position.
    pub message: String,
    /// Where.
    pub span: Span,
    /// Other places that belong to the message, each with a label.
    pub related: Vec<(Span, String)>,
}

impl Diagnostic {
    /// A diagnostic without related places.
    pub fn new(kind: DiagnosticKind, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            kind,
            message: message.into(),
            span,
            related: Vec::new(),
        }
    }

    /// Adds a related place.
    pub fn with(mut self, span: Span, label: impl Into<String>) -> Diagnostic {
        self.related.push((span, label.into()));
        self
    }
}
