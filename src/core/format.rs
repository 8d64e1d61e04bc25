//! Numbers as the reports print them: four significant digits, seconds in
//! a readable unit, vectors as tuples.

/// A number in a short, readable form: 4 significant digits, scientific
/// notation when very small or large.
pub fn format_number(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else if x == 0.0 {
        "0".into()
    } else if (1e-3..1e5).contains(&x.abs()) {
        let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.3e}")
    }
}

/// Seconds in a readable unit.
pub fn format_seconds(s: f64) -> String {
    if s < 1e-6 {
        format!("{:.1} ns", s * 1e9)
    } else if s < 1e-3 {
        format!("{:.1} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// A point or vector as `(x, y, z)`, each number as [`format_number`].
pub fn format_vec3(v: glam::DVec3) -> String {
    format!(
        "({}, {}, {})",
        format_number(v.x),
        format_number(v.y),
        format_number(v.z)
    )
}

/// A 2D point as `(x, y)`, each number as [`format_number`].
pub fn format_vec2(v: glam::Vec2) -> String {
    format!(
        "({}, {})",
        format_number(v.x as f64),
        format_number(v.y as f64)
    )
}

/// A count and its noun: "1 light", "3 lights".
pub fn format_count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// A number with three significant digits (an inspect panel's numbers).
pub fn num(x: f32) -> String {
    let x = x as f64;
    if x == 0.0 || !x.is_finite() || !(1e-3..1e5).contains(&x.abs()) {
        return format_number(x);
    }
    let digits = (2 - x.abs().log10().floor() as i32).clamp(0, 8) as usize;
    format!("{x:.digits$}")
}

/// An RGB value: one number when grey, else three.
pub fn rgb(v: glam::Vec3) -> String {
    if v.x == v.y && v.y == v.z {
        num(v.x)
    } else {
        format!("{} {} {}", num(v.x), num(v.y), num(v.z))
    }
}

/// A direction with two decimals.
pub fn direction(v: glam::Vec3) -> String {
    format!("({:.2}, {:.2}, {:.2})", v.x, v.y, v.z)
}
