//! Attribute access with positions: every value read from the file is checked here, and a
//! bad one becomes an [`Error`] naming the file, line:col, element, attribute and what was
//! expected (OpenDRIVE 1.8 XSD types `t_grEqZero`, `t_grZero`, `double`).

use std::cell::OnceCell;
use std::marker::PhantomData;
use std::path::Path;
use std::sync::Arc;

use roxmltree::{Document, Node};
use source::{LineIndex, SourcePos};

use crate::error::{Error, ErrorKind};
use crate::math::{Cubic, S_TOLERANCE};

/// The document being read and its path, for positions in errors.
pub(crate) struct Reader<'a, 'input> {
    path: &'a Path,
    /// The whole file's text (a chunk's document holds only a part of it).
    text: &'a str,
    /// Where the document's text starts in `text`, and how many bytes were put before it
    /// (a chunk's wrapping start tag): document byte b is file byte `start + b − prefix`.
    start: usize,
    prefix: usize,
    /// The file as shared by positions, and the index of its line starts, built on the first
    /// position asked for, so that each position costs a binary search, not a scan from the
    /// file's start (files with many warnings would otherwise take quadratic time).
    lines: OnceCell<(Arc<Path>, LineIndex)>,
    _doc: PhantomData<&'a Document<'input>>,
}

impl<'a, 'input: 'a> Reader<'a, 'input> {
    /// A reader over a parsed document of the whole file.
    pub(crate) fn new(doc: &'a Document<'input>, path: &'a Path) -> Self {
        Self::chunk(doc.input_text(), path, 0, 0)
    }

    /// A reader over the document of a part of the file `text` that starts at byte `start`,
    /// parsed with `prefix` bytes put before it.
    pub(crate) fn chunk(text: &'a str, path: &'a Path, start: usize, prefix: usize) -> Self {
        Self {
            path,
            text,
            start,
            prefix,
            lines: OnceCell::new(),
            _doc: PhantomData,
        }
    }

    /// The file and 1-based line:col of a byte offset of the document (column in
    /// characters, as roxmltree counts them).
    pub(crate) fn pos(&self, byte: usize) -> SourcePos {
        let byte = self.start + byte.saturating_sub(self.prefix);
        let (file, lines) = self
            .lines
            .get_or_init(|| (Arc::from(self.path), LineIndex::new(self.text)));
        lines.pos(file, self.text, byte)
    }

    /// An error at an element's start tag.
    pub(crate) fn error_at(&self, node: Node, kind: ErrorKind) -> Error {
        Error::at(kind, self.pos(node.range().start))
    }

    /// An error at an attribute's value (or the element, if the attribute is absent).
    fn error_at_attr(&self, node: Node, name: &str, kind: ErrorKind) -> Error {
        let byte = node
            .attribute_node(name)
            .map_or(node.range().start, |a| a.range_value().start);
        Error::at(kind, self.pos(byte))
    }

    /// An "expected …, found …" error for an attribute.
    pub(crate) fn invalid(&self, node: Node, name: &str, expected: &str, found: &str) -> Error {
        self.error_at_attr(
            node,
            name,
            ErrorKind::InvalidValue {
                element: node.tag_name().name().to_string(),
                attribute: name.to_string(),
                expected: expected.to_string(),
                found: found.to_string(),
            },
        )
    }

    /// An unknown-reference error for an attribute.
    pub(crate) fn unknown(&self, node: Node, name: &str, target: &str, id: &str) -> Error {
        self.error_at_attr(
            node,
            name,
            ErrorKind::UnknownReference {
                element: node.tag_name().name().to_string(),
                attribute: name.to_string(),
                target: target.to_string(),
                id: id.to_string(),
            },
        )
    }

    /// A required attribute's text.
    pub(crate) fn req_str(&self, node: Node<'a, 'input>, name: &str) -> Result<&'a str, Error> {
        node.attribute(name).ok_or_else(|| {
            self.error_at(
                node,
                ErrorKind::MissingAttribute {
                    element: node.tag_name().name().to_string(),
                    attribute: name.to_string(),
                },
            )
        })
    }

    /// A required, finite number.
    pub(crate) fn req_f64(&self, node: Node<'a, 'input>, name: &str) -> Result<f64, Error> {
        let text = self.req_str(node, name)?;
        self.number(node, name, text)
    }

    /// An optional finite number, `default` when absent.
    pub(crate) fn opt_f64(
        &self,
        node: Node<'a, 'input>,
        name: &str,
        default: f64,
    ) -> Result<f64, Error> {
        match node.attribute(name) {
            Some(text) => self.number(node, name, text),
            None => Ok(default),
        }
    }

    /// An optional finite number, `None` when absent.
    pub(crate) fn maybe_f64(
        &self,
        node: Node<'a, 'input>,
        name: &str,
    ) -> Result<Option<f64>, Error> {
        node.attribute(name)
            .map(|text| self.number(node, name, text))
            .transpose()
    }

    /// A required number > 0 (XSD `t_grZero`).
    pub(crate) fn req_positive(&self, node: Node<'a, 'input>, name: &str) -> Result<f64, Error> {
        let v = self.req_f64(node, name)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.invalid(node, name, "a length > 0", self.req_str(node, name)?))
        }
    }

    /// A required number ≥ 0 (XSD `t_grEqZero`).
    pub(crate) fn req_non_negative(
        &self,
        node: Node<'a, 'input>,
        name: &str,
    ) -> Result<f64, Error> {
        let v = self.req_f64(node, name)?;
        if v >= 0.0 {
            Ok(v)
        } else {
            Err(self.invalid(node, name, "a value >= 0", self.req_str(node, name)?))
        }
    }

    /// An optional number ≥ 0 (XSD `t_grEqZero`), `default` when absent.
    pub(crate) fn opt_non_negative(
        &self,
        node: Node<'a, 'input>,
        name: &str,
        default: f64,
    ) -> Result<f64, Error> {
        match node.attribute(name) {
            Some(_) => self.req_non_negative(node, name),
            None => Ok(default),
        }
    }

    /// A required `s` attribute in [0, road_length] (+ [`S_TOLERANCE`]); `what` names the
    /// element's start in the message.
    pub(crate) fn req_s_within(
        &self,
        node: Node<'a, 'input>,
        road_length: f64,
        what: &str,
    ) -> Result<f64, Error> {
        let s = self.req_non_negative(node, "s")?;
        if s > road_length + S_TOLERANCE {
            let expected = format!("{what} within the road length {road_length}");
            return Err(self.invalid(node, "s", &expected, self.req_str(node, "s")?));
        }
        Ok(s)
    }

    /// A required integer.
    pub(crate) fn req_i32(&self, node: Node<'a, 'input>, name: &str) -> Result<i32, Error> {
        let text = self.req_str(node, name)?;
        text.trim()
            .parse::<i32>()
            .map_err(|_| self.invalid(node, name, "an integer", text))
    }

    /// An optional unsigned integer, `default` when absent.
    pub(crate) fn opt_u32(
        &self,
        node: Node<'a, 'input>,
        name: &str,
        default: u32,
    ) -> Result<u32, Error> {
        match node.attribute(name) {
            Some(text) => text
                .trim()
                .parse::<u32>()
                .map_err(|_| self.invalid(node, name, "an unsigned integer", text)),
            None => Ok(default),
        }
    }

    /// An optional boolean (`true`/`false`/`1`/`0`), `default` when absent.
    pub(crate) fn opt_bool(
        &self,
        node: Node<'a, 'input>,
        name: &str,
        default: bool,
    ) -> Result<bool, Error> {
        match node.attribute(name) {
            None => Ok(default),
            Some("true" | "1" | "yes") => Ok(true),
            Some("false" | "0" | "no") => Ok(false),
            Some(other) => Err(self.invalid(node, name, "true or false", other)),
        }
    }

    fn number(&self, node: Node, name: &str, text: &str) -> Result<f64, Error> {
        match text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(self.invalid(node, name, "a finite number", text)),
        }
    }
}

/// The element children of `node` named `name`.
pub(crate) fn children<'a, 'input: 'a>(
    node: Node<'a, 'input>,
    name: &'static str,
) -> impl Iterator<Item = Node<'a, 'input>> {
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// The first element child of `node` named `name`.
pub(crate) fn child<'a, 'input: 'a>(
    node: Node<'a, 'input>,
    name: &'static str,
) -> Option<Node<'a, 'input>> {
    children(node, name).next()
}

/// Reads every `<item>` inside the optional `<container>` child of `node` with `f`.
pub(crate) fn read_nested<'a, 'input: 'a, T>(
    node: Node<'a, 'input>,
    container: &'static str,
    item: &'static str,
    f: impl FnMut(Node<'a, 'input>) -> Result<T, Error>,
) -> Result<Vec<T>, Error> {
    child(node, container)
        .into_iter()
        .flat_map(|c| children(c, item))
        .map(f)
        .collect()
}

/// A "missing child element" error.
pub(crate) fn missing(r: &Reader, node: Node, name: &str) -> Error {
    r.error_at(
        node,
        ErrorKind::MissingElement {
            element: node.tag_name().name().to_string(),
            child: name.to_string(),
        },
    )
}

/// Records `<name start a b c d>` under `node`, sorted by `start_attr`.
pub(crate) fn read_cubics(
    r: &Reader,
    node: Node,
    name: &'static str,
    start_attr: &str,
) -> Result<Vec<Cubic>, Error> {
    let mut out = Vec::new();
    for e in children(node, name) {
        out.push(Cubic {
            start: r.req_non_negative(e, start_attr)?,
            a: r.req_f64(e, "a")?,
            b: r.req_f64(e, "b")?,
            c: r.req_f64(e, "c")?,
            d: r.req_f64(e, "d")?,
        });
    }
    out.sort_by(|a, b| a.start.total_cmp(&b.start));
    Ok(out)
}
