//! A small SVG writer for the book's diagrams: lines, arrows, polygons,
//! circles and labels in world coordinates (y up), mapped into a picture
//! of a fixed size. Every diagram sits on its own light panel, so that it
//! reads the same in the book's light and dark themes; numbers are written
//! with two decimals, so that the same inputs give the same bytes.

use std::fmt::Write as _;

/// Ink: outlines and labels.
pub const INK: &str = "#1b1b1b";
/// Secondary lines: construction lines, grids, axes.
pub const GREY: &str = "#8a8a8a";
/// The thing the diagram is about (a ray, a lobe, the light path).
pub const BLUE: &str = "#1f5fa8";
/// What is wrong, missed or rejected; the light.
pub const RED: &str = "#c0392b";
/// What is right, hit or accepted.
pub const GREEN: &str = "#23803a";
/// A second quantity beside the first.
pub const ORANGE: &str = "#d2691e";
/// Light fills (areas, covered pixels).
pub const FILL_BLUE: &str = "#cfe0f5";
/// Light fill for a second kind of area.
pub const FILL_ORANGE: &str = "#fbe3cc";
/// Light fill for a third kind of area.
pub const FILL_GREEN: &str = "#d5efd9";

/// How a shape is stroked.
#[derive(Clone, Copy, Debug)]
pub struct Stroke {
    /// An SVG colour.
    pub colour: &'static str,
    /// Width in picture units.
    pub width: f64,
    /// Dashed (construction lines).
    pub dashed: bool,
}

impl Stroke {
    /// A solid line of `width` in `colour`.
    pub const fn solid(colour: &'static str, width: f64) -> Stroke {
        Stroke {
            colour,
            width,
            dashed: false,
        }
    }

    /// A dashed line of `width` in `colour`.
    pub const fn dashed(colour: &'static str, width: f64) -> Stroke {
        Stroke {
            colour,
            width,
            dashed: true,
        }
    }

    fn attrs(&self) -> String {
        let dash = if self.dashed {
            " stroke-dasharray=\"6 4\""
        } else {
            ""
        };
        format!(
            "stroke=\"{}\" stroke-width=\"{:.2}\"{dash}",
            self.colour, self.width
        )
    }
}

/// Where a label is anchored horizontally.
#[derive(Clone, Copy, Debug)]
pub enum Anchor {
    /// The label starts at the point.
    Start,
    /// The label is centred on the point.
    Middle,
    /// The label ends at the point.
    End,
}

/// A picture of `width` x `height` units showing the world rectangle
/// `[x0, x1] x [y0, y1]` (y up), with a margin.
pub struct Svg {
    width: f64,
    height: f64,
    world: [f64; 4],
    margin: f64,
    body: String,
}

/// Escapes text for SVG.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

impl Svg {
    /// A picture `width` units wide showing `world` = `[x0, x1, y0, y1]`
    /// with equal scales on both axes (so circles stay round); its height
    /// follows from the world's aspect.
    pub fn new(width: f64, world: [f64; 4]) -> Svg {
        let margin = 16.0;
        let [x0, x1, y0, y1] = world;
        let scale = (width - 2.0 * margin) / (x1 - x0);
        let height = (y1 - y0) * scale + 2.0 * margin;
        Svg {
            width,
            height,
            world,
            margin,
            body: String::new(),
        }
    }

    /// Picture units per world unit.
    pub fn scale(&self) -> f64 {
        (self.width - 2.0 * self.margin) / (self.world[1] - self.world[0])
    }

    /// A world point in picture coordinates.
    pub fn map(&self, p: (f64, f64)) -> (f64, f64) {
        let s = self.scale();
        (
            self.margin + (p.0 - self.world[0]) * s,
            self.margin + (self.world[3] - p.1) * s,
        )
    }

    /// A straight line from `a` to `b`.
    pub fn line(&mut self, a: (f64, f64), b: (f64, f64), stroke: Stroke) {
        let (a, b) = (self.map(a), self.map(b));
        let _ = writeln!(
            self.body,
            "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" {} stroke-linecap=\"round\"/>",
            a.0,
            a.1,
            b.0,
            b.1,
            stroke.attrs()
        );
    }

    /// A line from `a` to `b` with an arrow head at `b`.
    pub fn arrow(&mut self, a: (f64, f64), b: (f64, f64), stroke: Stroke) {
        self.line(a, b, stroke);
        let (pa, pb) = (self.map(a), self.map(b));
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        let len = (dx * dx + dy * dy).sqrt();
        if len < 1e-9 {
            return;
        }
        let (ux, uy) = (dx / len, dy / len);
        let size = 4.0 + 2.5 * stroke.width;
        let left = (
            pb.0 - size * ux - 0.5 * size * uy,
            pb.1 - size * uy + 0.5 * size * ux,
        );
        let right = (
            pb.0 - size * ux + 0.5 * size * uy,
            pb.1 - size * uy - 0.5 * size * ux,
        );
        let _ = writeln!(
            self.body,
            "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{}\"/>",
            pb.0, pb.1, left.0, left.1, right.0, right.1, stroke.colour
        );
    }

    /// A polyline through `points`, closed into a polygon when `fill` is
    /// given (use `"none"` for a closed outline).
    pub fn polyline(&mut self, points: &[(f64, f64)], stroke: Stroke, fill: Option<&str>) {
        let mut pts = String::new();
        for p in points {
            let q = self.map(*p);
            let _ = write!(pts, "{:.2},{:.2} ", q.0, q.1);
        }
        let (tag, fill) = match fill {
            Some(f) => ("polygon", f),
            None => ("polyline", "none"),
        };
        let _ = writeln!(
            self.body,
            "<{tag} points=\"{}\" fill=\"{fill}\" {} stroke-linejoin=\"round\"/>",
            pts.trim_end(),
            stroke.attrs()
        );
    }

    /// A filled polygon with no outline.
    pub fn area(&mut self, points: &[(f64, f64)], fill: &str) {
        let mut pts = String::new();
        for p in points {
            let q = self.map(*p);
            let _ = write!(pts, "{:.2},{:.2} ", q.0, q.1);
        }
        let _ = writeln!(
            self.body,
            "<polygon points=\"{}\" fill=\"{fill}\" stroke=\"none\"/>",
            pts.trim_end()
        );
    }

    /// A circle of world radius `r` around `c`.
    pub fn circle(&mut self, c: (f64, f64), r: f64, stroke: Stroke, fill: Option<&str>) {
        let p = self.map(c);
        let _ = writeln!(
            self.body,
            "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{:.2}\" fill=\"{}\" {}/>",
            p.0,
            p.1,
            r * self.scale(),
            fill.unwrap_or("none"),
            stroke.attrs()
        );
    }

    /// A dot of `radius` picture units at `c` (a vertex, a sample).
    pub fn dot(&mut self, c: (f64, f64), radius: f64, colour: &str) {
        let p = self.map(c);
        let _ = writeln!(
            self.body,
            "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{radius:.2}\" fill=\"{colour}\"/>",
            p.0, p.1
        );
    }

    /// A label at world point `at`, shifted by `(dx, dy)` picture units
    /// (dy down); `size` in picture units. Symbols (single letters, Greek)
    /// read best in italics: pass `italic`.
    #[allow(clippy::too_many_arguments)]
    pub fn text(
        &mut self,
        at: (f64, f64),
        offset: (f64, f64),
        label: &str,
        size: f64,
        anchor: Anchor,
        colour: &str,
        italic: bool,
    ) {
        let p = self.map(at);
        let anchor = match anchor {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        };
        let style = if italic { " font-style=\"italic\"" } else { "" };
        let _ = writeln!(
            self.body,
            "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"{size:.1}\" text-anchor=\"{anchor}\" fill=\"{colour}\"{style}>{}</text>",
            p.0 + offset.0,
            p.1 + offset.1,
            escape(label)
        );
    }

    /// A plain label (ink, 14 units, start-anchored) at `at`.
    pub fn label(&mut self, at: (f64, f64), label: &str) {
        self.text(at, (4.0, -4.0), label, 14.0, Anchor::Start, INK, false);
    }

    /// A caption line at the bottom of the picture, in picture units (it
    /// grows the picture by one line).
    pub fn caption(&mut self, label: &str) {
        let y = self.height + 4.0;
        self.height += 20.0;
        let _ = writeln!(
            self.body,
            "<text x=\"{:.2}\" y=\"{y:.2}\" font-size=\"13\" text-anchor=\"middle\" fill=\"{GREY}\">{}</text>",
            self.width / 2.0,
            escape(label)
        );
    }

    /// The finished document: the light panel, then the drawing.
    pub fn finish(&self) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w:.0}\" height=\"{h:.0}\" \
             viewBox=\"0 0 {w:.0} {h:.0}\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n\
             <rect x=\"0.5\" y=\"0.5\" width=\"{iw:.0}\" height=\"{ih:.0}\" rx=\"8\" fill=\"#ffffff\" stroke=\"#d0d0d0\"/>\n\
             {}</svg>\n",
            self.body,
            w = self.width,
            h = self.height.ceil(),
            iw = self.width - 1.0,
            ih = self.height.ceil() - 1.0,
        )
    }
}

impl Svg {
    /// Draws what `draw` draws clipped to the world rectangle `rect` =
    /// `[x0, x1, y0, y1]` (circles that would spill out of a panel).
    pub fn clipped(&mut self, rect: [f64; 4], draw: impl FnOnce(&mut Svg)) {
        let id = format!("clip{}", self.body.matches("<clipPath").count());
        let (a, b) = (self.map((rect[0], rect[3])), self.map((rect[1], rect[2])));
        let _ = writeln!(
            self.body,
            "<clipPath id=\"{id}\"><rect x=\"{:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\"/></clipPath>\n<g clip-path=\"url(#{id})\">",
            a.0,
            a.1,
            b.0 - a.0,
            b.1 - a.1
        );
        draw(self);
        self.body.push_str("</g>\n");
    }
}
