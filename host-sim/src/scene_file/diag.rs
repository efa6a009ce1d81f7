//! Diagnostics: an error or warning that names the file, the line and
//! column, and the field (`triangle[1].points[2]`) it is about.
//!
//! Semantic checks know their field and its byte span (every value is read
//! through `toml::Spanned`). Errors of the TOML parser or of serde (syntax,
//! unknown key, wrong type) carry only a span and a message; their field is
//! recovered from the source text: the table header above the span and the
//! key on the span's line.

use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// How bad a [`Diagnostic`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    /// The scene is rejected.
    Error,
    /// The scene is used, with the change the message names.
    Warning,
}

/// One message about a scene file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// The scene file.
    pub path: PathBuf,
    /// 1-based line (0 when the problem has no place in the file).
    pub line: usize,
    /// 1-based column, in characters (0 with `line`).
    pub column: usize,
    /// The field, as a path: `display.width`, `polygon[0].points[3]`.
    pub field: String,
    /// What is wrong, in words.
    pub message: String,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path.display())?;
        if self.line > 0 {
            write!(f, ":{}:{}", self.line, self.column)?;
        }
        if !self.field.is_empty() {
            write!(f, ": {}", self.field)?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for Diagnostic {}

/// Maps byte offsets of one source text to lines and columns.
#[derive(Debug, Clone)]
pub(crate) struct Source<'a> {
    pub path: &'a Path,
    pub text: &'a str,
}

impl<'a> Source<'a> {
    /// 1-based line and column of byte `offset` (clamped to the text).
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let mut end = offset.min(self.text.len());
        while !self.text.is_char_boundary(end) {
            end -= 1;
        }
        let before = &self.text[..end];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |k| k + 1);
        let column = before[line_start..].chars().count() + 1;
        (line, column)
    }

    /// A diagnostic at `span` about `field`.
    pub fn at(
        &self,
        severity: Severity,
        span: Range<usize>,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> Diagnostic {
        let (line, column) = self.line_col(span.start);
        Diagnostic {
            severity,
            path: self.path.to_path_buf(),
            line,
            column,
            field: field.into(),
            message: message.into(),
        }
    }

    /// An error at `span` about `field`.
    pub fn error(
        &self,
        span: Range<usize>,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> Diagnostic {
        self.at(Severity::Error, span, field, message)
    }

    /// The diagnostic for a parser or serde error.
    pub fn toml_error(&self, e: &toml::de::Error) -> Diagnostic {
        let message = e.message().trim().to_string();
        let Some(span) = e.span() else {
            return Diagnostic {
                severity: Severity::Error,
                path: self.path.to_path_buf(),
                line: 0,
                column: 0,
                field: missing_field(&message).unwrap_or_default(),
                message,
            };
        };
        let mut field = field_at(self.text, span.start);
        // A missing top-level table comes with an empty span at 0.
        let whole = span.start == 0 && span.is_empty();
        if let (true, Some(missing)) = (whole, missing_field(&message)) {
            // The whole document: a missing top-level table.
            field = missing;
        } else if let Some(name) = header_like(line_at(self.text, span.start)) {
            // On a table header: the table is the field (an unknown table,
            // a malformed header, a missing key of that table).
            field = name.to_string();
            if let Some(missing) = missing_field(&message) {
                field = join(&table_at(self.text, span.start), &missing);
            }
        } else if let Some(missing) = missing_field(&message) {
            field = join(&table_at(self.text, span.start), &missing);
        } else if let Some(unknown) = backticked(&message, "unknown field `") {
            // The span may sit on the table rather than on the key.
            if !field.ends_with(&unknown) {
                field = join(&table_at(self.text, span.start), &unknown);
            }
        }
        self.error(span, field, message)
    }
}

fn join(table: &str, key: &str) -> String {
    if table.is_empty() {
        key.to_string()
    } else {
        format!("{table}.{key}")
    }
}

/// The text between `prefix` and the next backtick of `message`.
fn backticked(message: &str, prefix: &str) -> Option<String> {
    let rest = &message[message.find(prefix)? + prefix.len()..];
    Some(rest[..rest.find('`')?].to_string())
}

fn missing_field(message: &str) -> Option<String> {
    backticked(message, "missing field `")
}

/// A table header line, `[name]` or `[[name]]` (a comment may follow),
/// as `(name, is_array)`. Lines of a multi-line array of numbers start with
/// `[` too; they are not headers because a name starts with a letter.
fn header(line: &str) -> Option<(&str, bool)> {
    let t = line.trim();
    let (inner, array) = if let Some(r) = t.strip_prefix("[[") {
        (r.split("]]").next()?, true)
    } else {
        (t.strip_prefix('[')?.split(']').next()?, false)
    };
    let name = inner.trim();
    let ok = name.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.\"".contains(c));
    ok.then_some((name, array))
}

/// The line holding byte `offset`.
fn line_at(text: &str, offset: usize) -> &str {
    let mut end = offset.min(text.len());
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    let start = text[..end].rfind('\n').map_or(0, |k| k + 1);
    let stop = text[end..].find('\n').map_or(text.len(), |k| end + k);
    &text[start..stop]
}

/// The name in a line that looks like a table header, even a malformed
/// one (`[[triangle]`): brackets, then a letter.
fn header_like(line: &str) -> Option<&str> {
    let inner = line.trim().strip_prefix('[')?.trim_start_matches('[');
    if !inner.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
        return None;
    }
    let end = inner.find([']', ' ', '#']).unwrap_or(inner.len());
    Some(&inner[..end])
}

/// The key a line assigns, `key = ...`, if it is one.
fn key_of(line: &str) -> Option<&str> {
    let (k, _) = line.split_once('=')?;
    let k = k.trim();
    let ok = !k.is_empty()
        && k.chars()
            .all(|c| c.is_ascii_alphanumeric() || "_-.\"".contains(c));
    ok.then_some(k)
}

/// The table (with its index, for arrays of tables) holding byte `offset`.
fn table_at(text: &str, offset: usize) -> String {
    field_and_table(text, offset).1
}

/// The field path at byte `offset`: the table and the last key assigned at
/// or before the offset's line.
fn field_at(text: &str, offset: usize) -> String {
    field_and_table(text, offset).0
}

fn field_and_table(text: &str, offset: usize) -> (String, String) {
    let mut counts: Vec<(String, usize)> = Vec::new();
    let mut table = String::new();
    let mut key: Option<String> = None;
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        if start > offset {
            break;
        }
        if let Some((name, array)) = header(line) {
            table = if array {
                let n = match counts.iter_mut().find(|(k, _)| k == name) {
                    Some((_, n)) => {
                        *n += 1;
                        *n
                    }
                    None => {
                        counts.push((name.to_string(), 0));
                        0
                    }
                };
                format!("{name}[{n}]")
            } else {
                name.to_string()
            };
            key = None;
        } else if let Some(k) = key_of(line) {
            key = Some(k.to_string());
        }
        start += line.len();
    }
    let field = match &key {
        Some(k) => join(&table, k),
        None => table.clone(),
    };
    (field, table)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "[display]\nwidth = 4\n[[triangle]]\npoints = [\n  [1.0, 2.0],\n]\n[[triangle]]\ncolors = 3\n";

    #[test]
    fn fields_come_from_headers_and_keys() {
        assert_eq!(field_at(DOC, DOC.find("4").unwrap()), "display.width");
        assert_eq!(
            field_at(DOC, DOC.find("[1.0").unwrap()),
            "triangle[0].points"
        );
        assert_eq!(
            field_at(DOC, DOC.find("3\n").unwrap()),
            "triangle[1].colors"
        );
        assert_eq!(table_at(DOC, DOC.len() - 1), "triangle[1]");
    }

    #[test]
    fn lines_and_columns_are_one_based() {
        let s = Source {
            path: Path::new("a.toml"),
            text: DOC,
        };
        assert_eq!(s.line_col(0), (1, 1));
        assert_eq!(s.line_col(DOC.find("4").unwrap()), (2, 9));
        assert_eq!(s.line_col(10_000).0, DOC.matches('\n').count() + 1);
        let d = s.error(10..11, "display.width", "too wide");
        assert_eq!(d.to_string(), "a.toml:2:1: display.width: too wide");
    }
}
