//! Plain-text tables for the reports, at most [`COLUMNS`] wide: a table
//! that does not fit puts its widest column under each row, or prints one
//! block per row.

use std::borrow::Cow;

use crate::core::text::shorten;

/// The most characters a table cell shows.
pub const CELL_CHARS: usize = 1024;

/// A titled table of text cells.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    /// Printed above the table.
    pub title: String,
    /// Column headers.
    pub columns: Vec<String>,
    /// Rows of cells.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// An empty table with headers.
    pub fn new(title: &str, columns: &[&str]) -> Table {
        Table {
            title: title.into(),
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row. A cell longer than [`CELL_CHARS`] is cut to that, so
    /// that a report stays small whatever a file names things.
    pub fn row(&mut self, cells: Vec<String>) {
        let cells = cells
            .into_iter()
            .map(|c| match shorten(&c, CELL_CHARS) {
                Cow::Borrowed(_) => c,
                Cow::Owned(short) => short,
            })
            .collect();
        self.rows.push(cells);
    }

    /// Aligned plain text, at most [`COLUMNS`] wide: one line per row
    /// when the table fits, else one block per row (the first cell as its
    /// heading, every other cell as `column: value` under it).
    pub fn to_text(&self) -> String {
        let n = self.columns.len();
        let mut widths: Vec<usize> = self.columns.iter().map(|c| c.chars().count()).collect();
        for r in &self.rows {
            for (i, c) in r.iter().enumerate().take(n) {
                widths[i] = widths[i].max(c.chars().count());
            }
        }
        let mut s = wrap(&self.title, "", "  ", COLUMNS);
        let total = 1 + widths.iter().map(|w| w + 2).sum::<usize>();
        // Too wide: the widest column but the first (notes, say) goes under
        // each row; if that is not enough, one block per row.
        let under = if total <= COLUMNS {
            None
        } else {
            let widest = (1..n).max_by_key(|&i| (widths[i], i));
            match widest {
                Some(i) if n > 2 && total - widths[i] - 2 <= COLUMNS => Some(i),
                _ => return s + &self.as_blocks(),
            }
        };
        let line = |cells: &[String], header: bool| {
            let mut s = String::from(" ");
            for (i, c) in cells.iter().enumerate().take(n) {
                if Some(i) == under {
                    continue;
                }
                let pad = widths[i].saturating_sub(c.chars().count());
                s += &format!(" {c}{} ", " ".repeat(pad));
            }
            let mut s = s.trim_end().to_string() + "\n";
            if let Some(i) = under.filter(|_| !header) {
                if let Some(cell) = cells.get(i).filter(|c| !c.is_empty()) {
                    let text = format!("{}: {cell}", self.columns[i]);
                    s += &wrap(&text, "      ", "        ", COLUMNS);
                }
            }
            s
        };
        s += &line(&self.columns, true);
        s += &format!(
            "  {}\n",
            widths
                .iter()
                .enumerate()
                .filter(|(i, _)| Some(*i) != under)
                .map(|(_, w)| "-".repeat(*w))
                .collect::<Vec<_>>()
                .join("  ")
        );
        for r in &self.rows {
            s += &line(r, false);
        }
        s
    }

    /// The rows as blocks: a table too wide for one line per row.
    fn as_blocks(&self) -> String {
        let mut s = String::new();
        for r in &self.rows {
            let Some((head, rest)) = r.split_first() else {
                continue;
            };
            s += &wrap(
                &format!("{}: {head}", self.columns[0]),
                "  - ",
                "      ",
                COLUMNS,
            );
            for (c, v) in self.columns.iter().skip(1).zip(rest) {
                if !v.is_empty() {
                    s += &wrap(&format!("{c}: {v}"), "      ", "        ", COLUMNS);
                }
            }
        }
        s
    }
}

/// The widest line a report prints.
pub const COLUMNS: usize = 100;

/// `text` wrapped at spaces to lines of at most `width` characters, the
/// first line starting with `first`, the others with `rest`; a word longer
/// than a line (a path, say) gets a line of its own. Ends with a newline.
pub fn wrap(text: &str, first: &str, rest: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line = first.to_string();
    let mut empty = true;
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let len = line.chars().count() + usize::from(!empty) + word.chars().count();
        if !empty && len > width {
            out += line.trim_end();
            out += "\n";
            line = rest.to_string();
            empty = true;
        }
        if !empty {
            line.push(' ');
        }
        line += word;
        empty = false;
    }
    out += line.trim_end();
    out + "\n"
}
