//! The reading context: the parsed documents, the parameter scope chain, the catalog index,
//! warnings, and the helpers every element reader uses to get at attributes and children.
//!
//! Every attribute goes through [`Ctx::req`]/[`Ctx::opt`], which resolve `$name` and `${…}`
//! (OpenSCENARIO 1.3 §9.1–9.2, in `resolve.rs`) before converting the text to the XSD type,
//! so parameter references work in any attribute. Errors point at the attribute's value.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use roxmltree::{Attribute, Document};

use crate::attr::FromAttr;
use crate::error::{Error, ErrorKind, Result};
use crate::expr::Value;
use crate::provider::FileProvider;
use crate::source::{LineIndex, SourcePos};
use crate::warning::Warning;

/// Deepest element nesting read (real scenarios nest about 25 deep).
pub(crate) const MAX_NESTING: usize = 256;

/// An element of one of the loaded documents.
pub(crate) type Node<'a> = roxmltree::Node<'a, 'a>;

/// One parsed file: its path, text, line index and tree.
pub(crate) struct Doc<'a> {
    /// The path as opened.
    pub path: Arc<Path>,
    /// The text.
    pub text: &'a str,
    /// Line starts of `text`.
    pub lines: LineIndex,
    /// The tree.
    pub doc: Document<'a>,
}

/// One level of parameter declarations: names and their typed values, in declaration order.
#[derive(Debug, Clone, Default)]
pub(crate) struct Scope {
    pub params: Vec<(String, Value)>,
}

/// An entity name used by an attribute, checked once all entities are known.
pub(crate) struct EntityUse {
    pub name: String,
    pub element: String,
    pub pos: SourcePos,
}

/// The state of one load.
pub(crate) struct Ctx<'a> {
    /// Where files are read and looked up.
    pub files: &'a dyn FileProvider,
    /// Index 0 is the scenario; catalogs follow.
    pub docs: &'a [Doc<'a>],
    /// The document the nodes being read belong to.
    pub cur: usize,
    /// Parameter scopes, outermost (global) first.
    pub scopes: Vec<Scope>,
    /// Deprecation and version warnings.
    pub warnings: Vec<Warning>,
    /// revMinor of each document's FileHeader (revMajor is 1), by document index.
    pub doc_rev_minor: Vec<u32>,
    /// The catalogs found through CatalogLocations.
    pub catalogs: CatalogIndex<'a>,
    /// Entity references to check after Entities is read.
    pub entity_uses: Vec<EntityUse>,
    /// The catalog entry (document, node) whose declarations are already in scope, with the
    /// reference's ParameterAssignments applied; [`Ctx::scoped`] must not declare them again.
    pub entry_scoped: Option<(usize, roxmltree::NodeId)>,
    /// Catalog entries being read, outermost first: (document, node, "catalog/entry").
    pub entry_stack: Vec<(usize, roxmltree::NodeId, String)>,
    /// Warnings found where only `&self` is at hand; merged by [`Ctx::take_warnings`].
    pub warnings_later: RefCell<Vec<Warning>>,
}

impl<'a> Ctx<'a> {
    /// The file and line:col of byte `offset` in the current document.
    pub fn pos_at(&self, offset: usize) -> SourcePos {
        let doc = &self.docs[self.cur];
        let (line, col) = doc.lines.line_col(doc.text, offset);
        SourcePos {
            file: doc.path.clone(),
            line,
            col,
        }
    }

    /// Where element `n` starts.
    pub fn pos(&self, n: Node<'a>) -> SourcePos {
        self.pos_at(n.range().start)
    }

    /// Where the value of attribute `a` starts.
    pub fn attr_pos(&self, a: &Attribute<'a, 'a>) -> SourcePos {
        self.pos_at(a.range_value().start)
    }

    /// An error at element `n`.
    pub fn err(&self, n: Node<'a>, kind: ErrorKind) -> Error {
        Error::new(kind, self.pos(n))
    }

    /// Records a warning at element `n`.
    pub fn warn(&mut self, n: Node<'a>, message: String) {
        let pos = self.pos(n);
        self.warnings.push(Warning { message, pos });
    }

    /// revMinor declared by the current document (3 when unknown).
    pub fn rev_minor(&self) -> u32 {
        self.doc_rev_minor.get(self.cur).copied().unwrap_or(3)
    }

    /// Warns when element `n` needs OpenSCENARIO 1.`minor` but its file declares less.
    pub fn since(&mut self, n: Node<'a>, minor: u32) {
        let declared = self.rev_minor();
        if declared < minor {
            let message = format!(
                "{} needs OpenSCENARIO 1.{minor}, but the file declares 1.{}",
                n.tag_name().name(),
                declared
            );
            self.warn(n, message);
        }
    }

    /// Attribute `name` of `n`, if written.
    pub fn raw_attr(&self, n: Node<'a>, name: &str) -> Option<Attribute<'a, 'a>> {
        n.attributes().find(|a| a.name() == name)
    }

    /// Optional attribute `name` of `n`, resolved and converted to `T`.
    pub fn opt<T: FromAttr>(&mut self, n: Node<'a>, name: &str) -> Result<Option<T>> {
        let Some(a) = self.raw_attr(n, name) else {
            return Ok(None);
        };
        let text = match self.resolve(n, &a) {
            Ok(text) => text,
            // esmini builds names with its own string expressions (`${Name_ + $p}`); a name
            // whose expression does not evaluate is kept as written, with a warning.
            Err(e) if name == "name" && matches!(e.kind(), ErrorKind::Expression { .. }) => {
                let message = format!("{}@name kept as written: {}", n.tag_name().name(), e.kind());
                self.warnings.push(Warning {
                    message,
                    pos: e.pos().clone(),
                });
                a.value().to_owned()
            }
            Err(e) => return Err(e),
        };
        match T::from_attr(&text) {
            Some((value, deprecated)) => {
                if deprecated {
                    let message = format!(
                        "{}@{name}: '{}' is a deprecated literal, read as '{}'",
                        n.tag_name().name(),
                        text.trim(),
                        value.literal()
                    );
                    let pos = self.attr_pos(&a);
                    self.warnings.push(Warning { message, pos });
                }
                Ok(Some(value))
            }
            None => Err(Error::new(
                ErrorKind::InvalidValue {
                    element: n.tag_name().name().to_owned(),
                    attribute: name.to_owned(),
                    expected: T::expected(),
                    found: text,
                },
                self.attr_pos(&a),
            )),
        }
    }

    /// Required attribute `name` of `n`, resolved and converted to `T`.
    pub fn req<T: FromAttr>(&mut self, n: Node<'a>, name: &'static str) -> Result<T> {
        let value = self.opt(n, name)?;
        self.required(n, name, value)
    }

    /// `value` of attribute `name` of `n`, or the error that the attribute is missing.
    fn required<T>(&self, n: Node<'a>, name: &'static str, value: Option<T>) -> Result<T> {
        value.ok_or_else(|| {
            self.err(
                n,
                ErrorKind::MissingAttribute {
                    element: n.tag_name().name().to_owned(),
                    attribute: name,
                },
            )
        })
    }

    /// Optional attribute `name` of `n`, a double the model documents with "Range: [0..inf["
    /// (Performance's maxima and rates, OpenSCENARIO XML 1.3 model documentation): a negative
    /// value is an error at the attribute, as a value outside the type is.
    pub fn opt_non_negative(&mut self, n: Node<'a>, name: &str) -> Result<Option<f64>> {
        let value: Option<f64> = self.opt(n, name)?;
        match (value, self.raw_attr(n, name)) {
            (Some(v), Some(a)) if v < 0.0 => Err(Error::new(
                ErrorKind::InvalidValue {
                    element: n.tag_name().name().to_owned(),
                    attribute: name.to_owned(),
                    expected: "a double of at least 0 (range [0..inf[)".into(),
                    found: v.to_string(),
                },
                self.attr_pos(&a),
            )),
            _ => Ok(value),
        }
    }

    /// Required attribute `name` of `n`, a double of the range [0..inf[ (see
    /// [`Ctx::opt_non_negative`]).
    pub fn req_non_negative(&mut self, n: Node<'a>, name: &'static str) -> Result<f64> {
        let value = self.opt_non_negative(n, name)?;
        self.required(n, name, value)
    }

    /// Required attribute `name` that names a parameter (ParameterDeclaration@name,
    /// ParameterAssignment@parameterRef, …): read as written, not resolved, a leading `$`
    /// dropped (scenariogeneration and esmini write one).
    pub fn param_name(&mut self, n: Node<'a>, name: &'static str) -> Result<String> {
        match self.raw_attr(n, name) {
            Some(a) => Ok(a.value().trim().trim_start_matches('$').to_owned()),
            None => Err(self.err(
                n,
                ErrorKind::MissingAttribute {
                    element: n.tag_name().name().to_owned(),
                    attribute: name,
                },
            )),
        }
    }

    /// As [`Ctx::param_name`], also checking that the parameter is declared in scope
    /// (ParameterCondition, ParameterAction refer to a declared parameter).
    pub fn declared_param(&mut self, n: Node<'a>, name: &'static str) -> Result<String> {
        let param = self.param_name(n, name)?;
        if self.lookup(&param).is_none() {
            let pos = self
                .raw_attr(n, name)
                .map_or_else(|| self.pos(n), |a| self.attr_pos(&a));
            let attribute = format!("{}@{name}", n.tag_name().name());
            return Err(Error::new(
                ErrorKind::UnknownParameter {
                    name: param,
                    attribute,
                },
                pos,
            ));
        }
        Ok(param)
    }

    /// All warnings so far, in the order found.
    pub fn take_warnings(&mut self) -> Vec<Warning> {
        let mut all = std::mem::take(&mut self.warnings);
        all.append(&mut self.warnings_later.borrow_mut());
        all
    }

    /// Required attribute `name` naming an entity; the name is checked once Entities is known.
    pub fn entity(&mut self, n: Node<'a>, name: &'static str) -> Result<String> {
        let value: String = self.req(n, name)?;
        self.note_entity(n, name, &value);
        Ok(value)
    }

    /// Optional attribute naming an entity.
    pub fn opt_entity(&mut self, n: Node<'a>, name: &'static str) -> Result<Option<String>> {
        let value: Option<String> = self.opt(n, name)?;
        if let Some(v) = &value {
            self.note_entity(n, name, v);
        }
        Ok(value)
    }

    fn note_entity(&mut self, n: Node<'a>, name: &str, value: &str) {
        let pos = self
            .raw_attr(n, name)
            .map_or_else(|| self.pos(n), |a| self.attr_pos(&a));
        let element = format!("{}@{name}", n.tag_name().name());
        self.entity_uses.push(EntityUse {
            name: value.to_owned(),
            element,
            pos,
        });
    }

    /// The first child element of `n` named `name`.
    pub fn opt_child(&self, n: Node<'a>, name: &str) -> Option<Node<'a>> {
        n.children()
            .find(|c| c.is_element() && c.tag_name().name() == name)
    }

    /// The required child element `name` of `n`.
    pub fn child(&self, n: Node<'a>, name: &str) -> Result<Node<'a>> {
        self.opt_child(n, name).ok_or_else(|| {
            self.err(
                n,
                ErrorKind::MissingElement {
                    parent: n.tag_name().name().to_owned(),
                    expected: name.to_owned(),
                },
            )
        })
    }

    /// All child elements of `n` named `name`, in document order.
    pub fn children(&self, n: Node<'a>, name: &'a str) -> impl Iterator<Item = Node<'a>> + 'a {
        n.children()
            .filter(move |c| c.is_element() && c.tag_name().name() == name)
    }

    /// The single element child of a choice element `n` (XSD `xsd:choice`); `expected` lists
    /// the allowed names for the error.
    pub fn choice(&self, n: Node<'a>, expected: &str) -> Result<Node<'a>> {
        n.children().find(Node::is_element).ok_or_else(|| {
            self.err(
                n,
                ErrorKind::MissingElement {
                    parent: n.tag_name().name().to_owned(),
                    expected: format!("one of {expected}"),
                },
            )
        })
    }

    /// Refuses elements nested deeper than [`MAX_NESTING`]: positions (RoutePosition →
    /// Route → Waypoint → Position) and trailers (Trailer → ScenarioObject → Vehicle →
    /// Trailer) nest recursively, and their readers recurse with them.
    pub fn check_depth(&self, n: Node<'a>) -> Result<()> {
        if n.ancestors().nth(MAX_NESTING).is_some() {
            return Err(self.err(
                n,
                ErrorKind::TooDeep {
                    element: n.tag_name().name().to_owned(),
                    limit: MAX_NESTING,
                },
            ));
        }
        Ok(())
    }

    /// Checks that every child element of the sequence element `n` is one of `allowed`, so a
    /// misspelt or misplaced element is an error rather than silently dropped.
    pub fn expect_children(&self, n: Node<'a>, allowed: &[&str]) -> Result<()> {
        match n
            .children()
            .find(|c| c.is_element() && !allowed.contains(&c.tag_name().name()))
        {
            Some(c) => Err(self.unexpected(n, c, &allowed.join(", "))),
            None => Ok(()),
        }
    }

    /// The error for child `found` of `parent` not being one of `expected`.
    pub fn unexpected(&self, parent: Node<'a>, found: Node<'a>, expected: &str) -> Error {
        self.err(
            found,
            ErrorKind::UnexpectedElement {
                parent: parent.tag_name().name().to_owned(),
                found: found.tag_name().name().to_owned(),
                expected: format!("one of {expected}"),
            },
        )
    }
}

/// One catalog file.
pub(crate) struct CatalogFile<'a> {
    /// `Catalog@name`.
    pub name: String,
    /// Index of the document in `Ctx::docs`.
    pub doc: usize,
    /// The `Catalog` element.
    pub node: Node<'a>,
}

/// The catalogs found through CatalogLocations.
#[derive(Default)]
pub(crate) struct CatalogIndex<'a> {
    /// Directories searched, as resolved.
    pub dirs: Vec<PathBuf>,
    /// Those of `dirs` that do not exist.
    pub missing_dirs: Vec<PathBuf>,
    /// Catalog files, in directory order.
    pub files: Vec<CatalogFile<'a>>,
}
