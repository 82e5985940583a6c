//! Source snippets for errors at a file position: the line of a scenario or catalog file
//! (OpenSCENARIO XML) an error names, with the offending span marked, rendered by miette as
//! users of Rust tools expect (`oscsim validate`).

use std::ops::Range;

use scenario::SourcePos;
use source::LineIndex;

/// Files larger than this are not read again for a snippet (the loader refuses them anyway).
const MAX_SNIPPET_FILE: u64 = scenario::MAX_FILE_BYTES;

/// The miette report of `message` at `pos`, with the file's text around it and the span at
/// `pos` marked; `None` when the file cannot be read again or `pos` lies outside it.
pub fn render(message: &str, pos: &SourcePos) -> Option<String> {
    let size = std::fs::metadata(&pos.file).ok()?.len();
    if size > MAX_SNIPPET_FILE {
        return None;
    }
    let text = std::fs::read_to_string(&pos.file).ok()?;
    let span = span_at(&text, pos.line, pos.col)?;
    let diagnostic = miette::MietteDiagnostic::new(message.to_owned())
        .with_labels([miette::LabeledSpan::at(span, "here")]);
    let name = pos.file.display().to_string();
    let report =
        miette::Report::new(diagnostic).with_source_code(miette::NamedSource::new(name, text));
    let handler =
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
            .with_width(160);
    let mut out = String::new();
    handler.render_report(&mut out, report.as_ref()).ok()?;
    Some(out)
}

/// The byte range of the token at 1-based `line`:`col` (columns count characters): an
/// attribute's value when the column is its first character, an element start `<Name`, an
/// attribute `name="value"` with its value, or else the run of characters up to white space,
/// `>`, `/` or the end of the line (at least one character).
fn span_at(text: &str, line: u32, col: u32) -> Option<Range<usize>> {
    let range = LineIndex::new(text).line_range(text, line.max(1))?;
    let line_start = range.start;
    let line_text = &text[range];
    let offset = line_text
        .char_indices()
        .nth(col.saturating_sub(1) as usize)
        .map_or(line_text.len(), |(i, _)| i);
    let token = &line_text[offset..];
    if line_text[..offset].ends_with('"') {
        // Inside an attribute value (the reader points at a value's first character): the
        // value up to its closing quote.
        if let Some(close) = token.find('"') {
            let start = line_start + offset;
            return Some(start..start + close.max(1));
        }
    }
    let mut len = token
        .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
        .unwrap_or(token.len());
    if let Some(eq) = token[..len].find("=\"") {
        // An attribute: through the closing quote of its value (on this line).
        if let Some(close) = token[eq + 2..].find('"') {
            len = eq + 2 + close + 1;
        }
    }
    if len == 0 {
        len = token.chars().next().map_or(0, char::len_utf8);
    }
    let start = line_start + offset;
    Some(start..start + len)
}

#[cfg(test)]
mod tests {
    use super::span_at;

    const XML: &str =
        "<OpenSCENARIO>\n  <RoadNetwork>\n    <LogicFile filepath=\"no such.xodr\"/>\n";

    #[test]
    fn spans_an_element_or_an_attribute() {
        // Line 2, column 3: "<RoadNetwork" starts at byte 15 + 2 = 17, 12 bytes long.
        assert_eq!(span_at(XML, 2, 3), Some(17..29));
        assert_eq!(&XML[17..29], "<RoadNetwork");
        // Line 3, column 16: the attribute filepath="no such.xodr" (23 bytes), value included
        // although it holds a space.
        let start = XML.find("filepath").expect("in the text");
        assert_eq!(span_at(XML, 3, 16), Some(start..start + 23));
        // Line 3, column 26: the value no such.xodr (12 bytes), as the reader points at it.
        let value = XML.find("no such").expect("in the text");
        assert_eq!(span_at(XML, 3, 26), Some(value..value + 12));
        // The empty line after the last line end: an empty span at the end, no panic.
        assert_eq!(span_at(XML, 4, 1), Some(XML.len()..XML.len()));
        // A line past the end has no span.
        assert_eq!(span_at(XML, 9, 1), None);
    }
}
