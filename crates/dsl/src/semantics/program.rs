//! The front door: load a file with its imports and the standard library, check it, resolve it;
//! and the crate's one error, [`Error`] (a check's or a resolution's [`Diagnostics`]).
//!
//! Files `0..L` of a program are the standard library (`osc.standard`, always loaded: a file
//! with or without `import osc.standard` sees the same declarations, behind its own, see
//! `namespace.rs`); then the main file and the files it imports by relative path (ASAM
//! OpenSCENARIO DSL 2.1 §7.7.5 import mechanism), each once.

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use source::{LineIndex, SourcePos};

use crate::syntax::parse;

use super::check::{check_model, Invocation, Template};
use super::collect::collect;
use super::declarations;
use super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::hir::{FileId, ImportTarget, Item, SourceFile, Span};
use super::lower_ast::lower_file;
use super::model::Model;
use super::namespace::resolve_namespaces;
use super::resolve::{resolve, Resolution};
use super::stdlib;

/// One source file of a program.
#[derive(Debug, Clone)]
pub struct Source {
    /// Its name in messages (the path as given, or `osc/standard/objects.osc`).
    pub name: String,
    /// Its text.
    pub text: String,
    /// `name` as the file of positions.
    file: Arc<Path>,
    index: LineIndex,
}

/// Two sources are equal when their names and texts are (the index and the position file are
/// made from them).
impl PartialEq for Source {
    fn eq(&self, other: &Source) -> bool {
        self.name == other.name && self.text == other.text
    }
}

impl Source {
    fn new(name: String, text: String) -> Source {
        let index = LineIndex::new(&text);
        let file = Arc::from(Path::new(&name));
        Source {
            name,
            text,
            file,
            index,
        }
    }

    /// 1-based line and column of a byte offset.
    pub fn line_col(&self, offset: u32) -> (usize, usize) {
        let (line, col) = self.index.line_col(&self.text, offset as usize);
        (line as usize, col as usize)
    }

    /// The position (this file, 1-based line:col) of a byte offset.
    pub fn pos(&self, offset: u32) -> SourcePos {
        self.index.pos(&self.file, &self.text, offset as usize)
    }
}

/// The position of `span`'s start in `files`; a span into no file (none is made) is `?:1:1`.
pub fn source_pos(files: &[Source], span: Span) -> SourcePos {
    match files.get(span.file.0 as usize) {
        Some(f) => f.pos(span.start),
        None => SourcePos::start_of(Arc::from(Path::new("?"))),
    }
}

/// Errors of a program, with the files they point into (never empty: an [`Error`] is made with
/// at least one).
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostics {
    /// The errors, in the order found.
    pub items: Vec<Diagnostic>,
    files: Arc<Vec<Source>>,
}

impl Diagnostics {
    /// The position (file, 1-based line:col) of a span's start.
    pub fn source_pos(&self, span: Span) -> SourcePos {
        source_pos(&self.files, span)
    }

    /// The position of the first error (in source order for a check's errors).
    pub fn pos(&self) -> Option<SourcePos> {
        self.items.first().map(|d| self.source_pos(d.span))
    }

    /// `FILE:LINE:COL` of a span.
    pub fn position(&self, span: Span) -> String {
        self.source_pos(span).to_string()
    }

    /// One line per error: "MESSAGE at FILE:LINE:COL", each related place on an indented
    /// line "LABEL at FILE:LINE:COL".
    pub fn lines(&self) -> Vec<String> {
        let mut out = Vec::new();
        for d in &self.items {
            out.push(format!("{} at {}", d.message, self.position(d.span)));
            for (s, label) in &d.related {
                out.push(format!("  {label} at {}", self.position(*s)));
            }
        }
        out
    }

    /// A miette report per error, with the source snippet and the related places labelled.
    pub fn reports(&self) -> Vec<miette::Report> {
        self.items
            .iter()
            .map(|d| {
                let file = self.files.get(d.span.file.0 as usize);
                let mut m = miette::MietteDiagnostic::new(d.message.clone())
                    .with_code(d.kind.code())
                    .with_label(miette::LabeledSpan::at(
                        d.span.start as usize..d.span.end as usize,
                        "here",
                    ));
                for (s, label) in &d.related {
                    if s.file == d.span.file {
                        m = m.and_label(miette::LabeledSpan::at(
                            s.start as usize..s.end as usize,
                            label.clone(),
                        ));
                    } else {
                        m = m.with_help(format!("{label} at {}", self.position(*s)));
                    }
                }
                let report = miette::Report::new(m);
                match file {
                    Some(f) => report
                        .with_source_code(miette::NamedSource::new(f.name.clone(), f.text.clone())),
                    None => report,
                }
            })
            .collect()
    }
}

impl fmt::Display for Diagnostics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.lines().join("\n"))
    }
}

/// What went wrong: the kinds of [`Error`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The program did not pass the language checks (it cannot be read, an import, a syntax
    /// error, names, types and units, arguments, modifiers): every error, in source order.
    Check(Diagnostics),
    /// The program's constraints could not be solved with the seed (no solution, or a form
    /// the solver does not handle); the check solves them with seed 0.
    Resolve(Diagnostics),
}

/// The crate's one error: a program that does not check, or whose constraints do not resolve.
/// Its text is one line per error, "MESSAGE at FILE:LINE:COL" (each related place on an
/// indented line after it, [`Diagnostics::lines`]); [`Error::pos`] is the first error's place.
///
/// The parser itself never fails: its [`SyntaxError`](crate::syntax::SyntaxError)s are data of
/// a [`Parse`](crate::syntax::Parse) (a byte range in a text without a file), which the check
/// reports as [`ErrorKind::Check`] errors of kind `osc::syntax` at their file's line and column.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    kind: Box<ErrorKind>,
}

impl Error {
    fn check(items: Vec<Diagnostic>, files: Arc<Vec<Source>>) -> Error {
        Error {
            kind: Box::new(ErrorKind::Check(Diagnostics { items, files })),
        }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// Every error, with the files they point into.
    pub fn diagnostics(&self) -> &Diagnostics {
        match &*self.kind {
            ErrorKind::Check(d) | ErrorKind::Resolve(d) => d,
        }
    }

    /// Where: the first error's file and 1-based line and column (`?:1:1`, the place of a span
    /// into no file, for a list of no errors, which is never made).
    pub fn pos(&self) -> SourcePos {
        self.diagnostics()
            .pos()
            .unwrap_or_else(|| SourcePos::start_of(Arc::from(Path::new("?"))))
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.diagnostics().fmt(f)
    }
}

/// The text names every error and its place, so the error has no `source`.
impl std::error::Error for Error {}

/// A program that passed the checks: its declarations and constraints.
#[derive(Debug, Clone)]
pub struct CheckedProgram {
    /// The declarations.
    pub model: Model,
    /// The constraints (including field defaults).
    pub templates: Vec<Template>,
    /// The invocations of behaviors with a `do` (each an instance with its own parameters).
    pub invocations: Vec<Invocation>,
    files: Arc<Vec<Source>>,
}

impl CheckedProgram {
    /// Concrete values of every field of every global, top-level field and scenario, sampled
    /// with `seed` where the constraints leave a choice (same seed, same values).
    pub fn resolve(&self, seed: u64) -> Result<Resolution, Error> {
        resolve(&self.model, &self.templates, &self.invocations, seed).map_err(|items| Error {
            kind: Box::new(ErrorKind::Resolve(Diagnostics {
                items,
                files: self.files.clone(),
            })),
        })
    }

    /// The program's files (library first).
    pub fn files(&self) -> &[Source] {
        &self.files
    }
}

/// Checks the file at `path` with its imports.
pub fn check(path: &Path) -> Result<CheckedProgram, Error> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        let files = Arc::new(vec![Source::new(path.display().to_string(), String::new())]);
        let span = Span {
            file: FileId(0),
            start: 0,
            end: 0,
        };
        Error::check(
            vec![Diagnostic::new(
                K::Import,
                span,
                format!("cannot read {}: {e}", path.display()),
            )],
            files,
        )
    })?;
    check_source_with(&path.display().to_string(), &text, &|p: &Path| {
        std::fs::read_to_string(p).ok()
    })
}

/// Checks a source text; relative imports are read from disk next to `name`.
pub fn check_source(name: &str, text: &str) -> Result<CheckedProgram, Error> {
    check_source_with(name, text, &|p: &Path| std::fs::read_to_string(p).ok())
}

/// Checks a source text, reading relative imports through `load`.
pub fn check_source_with(
    name: &str,
    text: &str,
    load: &dyn Fn(&Path) -> Option<String>,
) -> Result<CheckedProgram, Error> {
    let mut files: Vec<Source> = stdlib::STANDARD
        .iter()
        .map(|f| Source::new(f.name.to_string(), f.text.to_string()))
        .collect();
    let library = files.len() as u32;
    let mut paths: Vec<PathBuf> = Vec::new();
    files.push(Source::new(name.to_string(), text.to_string()));
    paths.push(PathBuf::from(name));
    let mut hir: Vec<SourceFile> = Vec::new();
    let mut diags = Vec::new();
    let mut i = 0;
    while i < files.len() {
        let parsed = parse(&files[i].text);
        for e in parsed.errors() {
            let r = e.range();
            diags.push(Diagnostic::new(
                K::Syntax,
                Span {
                    file: FileId(i as u32),
                    start: r.start as u32,
                    end: r.end as u32,
                },
                e.message(),
            ));
        }
        let file = lower_file(&parsed.tree(), FileId(i as u32));
        for item in &file.items {
            let Item::Import { target, span } = item else {
                continue;
            };
            match target {
                ImportTarget::Library(q) => {
                    if stdlib::module(&q.text()).is_none() {
                        diags.push(Diagnostic::new(
                            K::Import,
                            *span,
                            format!("unknown library `{}` (known: osc.standard)", q.text()),
                        ));
                    }
                }
                ImportTarget::File(rel) if (i as u32) >= library => {
                    let base = paths[i - library as usize]
                        .parent()
                        .map(Path::to_path_buf)
                        .unwrap_or_default();
                    let full = base.join(rel);
                    if paths.contains(&full) {
                        continue;
                    }
                    match load(&full) {
                        Some(t) => {
                            files.push(Source::new(full.display().to_string(), t));
                            paths.push(full);
                        }
                        None => diags.push(Diagnostic::new(
                            K::Import,
                            *span,
                            format!("cannot read imported file {}", full.display()),
                        )),
                    }
                }
                ImportTarget::File(_) => {}
            }
        }
        hir.push(file);
        i += 1;
    }
    let files = Arc::new(files);
    if !diags.is_empty() {
        return Err(Error::check(diags, files));
    }
    let namespaces: Vec<&'static str> = stdlib::STANDARD.iter().map(|f| f.namespace).collect();
    resolve_namespaces(&mut hir, &namespaces, &mut diags);
    let mut model = collect(&hir, &mut diags);
    model.library_files = library;
    declarations::check(&model, &mut diags);
    let checked = check_model(&model);
    diags.extend(checked.diags);
    model.enum_member_names = checked.enum_member_names;
    // Report in source order, whichever pass found them.
    diags.sort_by_key(|d| (d.span.file, d.span.start));
    // A name the namespace pass explained is not reported again as unknown by the checker.
    diags.dedup_by(|later, first| {
        later.span == first.span && later.kind == K::UnknownName && first.kind == K::UnknownName
    });
    if !diags.is_empty() {
        return Err(Error::check(diags, files));
    }
    let program = CheckedProgram {
        model,
        templates: checked.templates,
        invocations: checked.invocations,
        files,
    };
    // A program whose constraints cannot be lowered or have no solution is not valid.
    program.resolve(0)?;
    Ok(program)
}
