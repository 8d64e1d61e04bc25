//! `[[sdfs]]` entries of a scene file → [`Sdf`] trees.
//!
//! An entry is one node: a primitive or an operator, named by `type`, with
//! that type's keys, an optional transform (`scale`, then `rotate`, then
//! `translate`, as for meshes) and, at the top level only, `name` and
//! `material`. Operators take their operands as `of = [ {...}, {...} ]`,
//! inline tables that are nodes themselves. Every error names the key
//! path, e.g. `sdfs[2].of[1].radius`.

use glam::{Quat, Vec3};
use toml::{Table, Value};

use super::sdf::{ScaleBound, Sdf};
use super::validate::{MAX_COORDINATE, MIN_LENGTH};

/// An error: (key path, message).
pub type ParseError = (String, String);

/// The node types and the keys each one takes (besides the transform).
pub const TYPES: &[(&str, &[&str])] = &[
    ("sphere", &["radius"]),
    ("box", &["size"]),
    ("rounded_box", &["size", "radius"]),
    ("torus", &["major", "minor"]),
    ("plane", &["normal", "offset"]),
    ("capsule", &["a", "b", "radius"]),
    ("cylinder", &["radius", "height"]),
    ("union", &["of"]),
    ("intersection", &["of"]),
    ("difference", &["of"]),
    ("smooth_union", &["of", "k"]),
];

const TRANSFORM_KEYS: &[&str] = &["scale", "scale_bound", "rotate", "translate"];
const TOP_KEYS: &[&str] = &["name", "material"];

/// Parses one node at key path `at`; `top` allows `name` and `material`.
pub fn parse_node(t: &Table, at: &str, top: bool) -> Result<Sdf, ParseError> {
    let err = |key: &str, msg: String| (format!("{at}.{key}"), msg);
    let kind = match t.get("type") {
        Some(Value::String(s)) => s.as_str(),
        Some(v) => return Err(err("type", format!("expected a string, got {v}"))),
        None => {
            return Err((
                at.to_string(),
                format!("missing `type`; one of {}", type_names()),
            ))
        }
    };
    let Some((_, own_keys)) = TYPES.iter().find(|(name, _)| *name == kind) else {
        return Err(err(
            "type",
            format!(
                "unknown SDF type `{kind}`{}; one of {}",
                suggest(kind, TYPES.iter().map(|(n, _)| *n)),
                type_names()
            ),
        ));
    };
    // Every key must belong to this type, the transform, or the top level.
    for key in t.keys() {
        let known = key == "type"
            || own_keys.contains(&key.as_str())
            || TRANSFORM_KEYS.contains(&key.as_str())
            || (top && TOP_KEYS.contains(&key.as_str()));
        if !known {
            let mut allowed: Vec<&str> = own_keys.to_vec();
            allowed.extend(TRANSFORM_KEYS);
            if top {
                allowed.extend(TOP_KEYS);
            }
            let where_ = if TOP_KEYS.contains(&key.as_str()) {
                " (only a top-level [[sdfs]] entry has a name and material)".to_string()
            } else {
                format!(
                    "{}; `{kind}` takes {allowed:?}",
                    suggest(key, allowed.iter().copied())
                )
            };
            return Err(err(key, format!("unknown key{where_}")));
        }
    }
    let num = |key: &str, default: f32| number(t, key, default).map_err(|m| err(key, m));
    let positive = |key: &str, default: f32| {
        let v = num(key, default)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(err(key, format!("must be a positive number, got {v}")))
        }
    };
    let vec = |key: &str, default: Vec3| vec3(t, key, default).map_err(|m| err(key, m));
    let size = |default: f32| {
        let s = vec("size", Vec3::splat(default))?;
        if s.min_element() > 0.0 {
            Ok(s * 0.5)
        } else {
            Err(err("size", format!("expected 3 positive numbers, got {s}")))
        }
    };
    let shape = match kind {
        "sphere" => Sdf::Sphere {
            radius: positive("radius", 1.0)?,
        },
        "box" => Sdf::Box {
            half_size: size(1.0)?,
        },
        "rounded_box" => {
            let half_size = size(1.0)?;
            let radius = positive("radius", 0.1)?;
            if radius > half_size.min_element() {
                return Err(err(
                    "radius",
                    format!(
                        "{radius} is more than half the smallest side ({})",
                        half_size.min_element()
                    ),
                ));
            }
            Sdf::RoundedBox { half_size, radius }
        }
        "torus" => Sdf::Torus {
            major: positive("major", 1.0)?,
            minor: positive("minor", 0.25)?,
        },
        "plane" => {
            let n = vec("normal", Vec3::Y)?;
            let normal = n.try_normalize().ok_or_else(|| {
                let values = n.as_dvec3().to_array();
                err("normal", crate::scene::validate::direction_problem(&values))
            })?;
            Sdf::Plane {
                normal,
                offset: num("offset", 0.0)?,
            }
        }
        "capsule" => Sdf::Capsule {
            a: vec("a", Vec3::new(0.0, -0.5, 0.0))?,
            b: vec("b", Vec3::new(0.0, 0.5, 0.0))?,
            radius: positive("radius", 0.25)?,
        },
        "cylinder" => Sdf::Cylinder {
            radius: positive("radius", 0.5)?,
            half_height: positive("height", 1.0)? * 0.5,
        },
        _ => {
            let of = operands(t, at)?;
            match kind {
                "union" => Sdf::Union(of),
                "intersection" => Sdf::Intersection(of),
                "smooth_union" => Sdf::SmoothUnion {
                    k: {
                        let k = num("k", 0.25)?;
                        if k >= 0.0 {
                            k
                        } else {
                            return Err(err("k", format!("must not be negative, got {k}")));
                        }
                    },
                    of,
                },
                _ => {
                    // difference: the first minus all the others.
                    let mut it = of.into_iter();
                    let first = it.next().expect("operands() checked there are two");
                    let rest: Vec<Sdf> = it.collect();
                    let cut = if rest.len() == 1 {
                        rest.into_iter().next().expect("one")
                    } else {
                        Sdf::Union(rest)
                    };
                    Sdf::Difference(Box::new(first), Box::new(cut))
                }
            }
        }
    };
    transform(t, at, shape)
}

fn operands(t: &Table, at: &str) -> Result<Vec<Sdf>, ParseError> {
    let key = format!("{at}.of");
    let Some(Value::Array(items)) = t.get("of") else {
        return Err((
            key,
            "expected `of = [ { type = ... }, { type = ... } ]`, the shapes to combine".into(),
        ));
    };
    if items.len() < 2 {
        return Err((key, format!("needs at least 2 shapes, got {}", items.len())));
    }
    items
        .iter()
        .enumerate()
        .map(|(i, v)| match v {
            Value::Table(child) => parse_node(child, &format!("{key}[{i}]"), false),
            other => Err((
                format!("{key}[{i}]"),
                format!("expected an inline table {{ type = ... }}, got {other}"),
            )),
        })
        .collect()
}

/// scale, then rotate, then translate.
fn transform(t: &Table, at: &str, shape: Sdf) -> Result<Sdf, ParseError> {
    let err = |key: &str, msg: String| (format!("{at}.{key}"), msg);
    let mut s = shape;
    let bound = match t.get("scale_bound") {
        None => None,
        Some(Value::String(b)) if b == "min" => Some(ScaleBound::Min),
        Some(Value::String(b)) if b == "max" => Some(ScaleBound::Max),
        Some(v) => {
            return Err(err(
                "scale_bound",
                format!("expected \"min\" (safe) or \"max\" (overestimates), got {v}"),
            ))
        }
    };
    match t.get("scale") {
        None if bound.is_some() => {
            return Err(err(
                "scale_bound",
                "applies only with a per-axis `scale = [x, y, z]`".into(),
            ))
        }
        None => {}
        Some(Value::Array(_)) => {
            let factors = vec3(t, "scale", Vec3::ONE).map_err(|m| err("scale", m))?;
            check_scale(factors).map_err(|m| err("scale", m))?;
            s = Sdf::ScaleAxes {
                factors,
                bound: bound.unwrap_or(ScaleBound::Min),
                of: Box::new(s),
            };
        }
        Some(_) => {
            if bound.is_some() {
                return Err(err(
                    "scale_bound",
                    "applies only with a per-axis `scale = [x, y, z]`".into(),
                ));
            }
            let factor = number(t, "scale", 1.0).map_err(|m| err("scale", m))?;
            check_scale(Vec3::splat(factor)).map_err(|m| err("scale", m))?;
            s = Sdf::Scale {
                factor,
                of: Box::new(s),
            };
        }
    }
    if let Some(r) = t.get("rotate") {
        let Value::Table(r) = r else {
            return Err(err(
                "rotate",
                "expected { axis = [x, y, z], degrees = a }".into(),
            ));
        };
        if let Some(k) = r.keys().find(|k| *k != "axis" && *k != "degrees") {
            return Err(err(
                &format!("rotate.{k}"),
                "unknown key; `rotate` takes `axis` and `degrees`".into(),
            ));
        }
        let axis = vec3(r, "axis", Vec3::ZERO)
            .map_err(|m| err("rotate.axis", m))?
            .try_normalize()
            .ok_or_else(|| err("rotate.axis", "must be given and not zero".into()))?;
        let degrees = number(r, "degrees", 0.0).map_err(|m| err("rotate.degrees", m))?;
        s = Sdf::Rotate {
            rotation: Quat::from_axis_angle(axis, degrees.to_radians()),
            of: Box::new(s),
        };
    }
    if t.contains_key("translate") {
        let offset = vec3(t, "translate", Vec3::ZERO).map_err(|m| err("translate", m))?;
        s = Sdf::Translate {
            offset,
            of: Box::new(s),
        };
    }
    Ok(s)
}

/// A number of an SDF as the renderer computes it, bounded like a mesh's:
/// within ±[`MAX_COORDINATE`], and zero or at least [`MIN_LENGTH`] in size
/// (a subnormal scale made a plane vanish).
fn as_f32(v: &Value) -> Option<f32> {
    let x = match v {
        Value::Float(f) => *f,
        Value::Integer(i) => *i as f64,
        _ => return None,
    };
    let bounded = x.is_finite() && x.abs() <= MAX_COORDINATE && (x == 0.0 || x.abs() >= MIN_LENGTH);
    bounded.then_some(x as f32)
}

/// What [`as_f32`] accepts, for messages.
fn bounds() -> String {
    format!("within ±{MAX_COORDINATE:e}, and 0 or at least {MIN_LENGTH:e} in size")
}

/// The range of a scale factor: past it, a point's distance to the scaled
/// shape overflows or underflows f32 somewhere in a scene of sensible size.
const SCALE_RANGE: std::ops::RangeInclusive<f32> = 1e-6..=1e6;

fn check_scale(factors: Vec3) -> Result<(), String> {
    if factors.to_array().iter().all(|f| SCALE_RANGE.contains(f)) {
        Ok(())
    } else {
        Err(format!(
            "factors must lie in [{:e}, {:e}] (f32 distances overflow or vanish past them), got {factors}",
            SCALE_RANGE.start(),
            SCALE_RANGE.end()
        ))
    }
}

fn number(t: &Table, key: &str, default: f32) -> Result<f32, String> {
    match t.get(key) {
        None => Ok(default),
        Some(v) => {
            as_f32(v).ok_or_else(|| format!("expected a finite number {}, got {v}", bounds()))
        }
    }
}

fn vec3(t: &Table, key: &str, default: Vec3) -> Result<Vec3, String> {
    match t.get(key) {
        None => Ok(default),
        Some(Value::Array(a)) if a.len() == 3 => {
            let xs: Option<Vec<f32>> = a.iter().map(as_f32).collect();
            xs.map(|x| Vec3::new(x[0], x[1], x[2])).ok_or_else(|| {
                format!(
                    "expected 3 finite numbers {}, got {}",
                    bounds(),
                    Value::Array(a.clone())
                )
            })
        }
        Some(v) => Err(format!("expected [x, y, z], got {v}")),
    }
}

fn type_names() -> String {
    TYPES
        .iter()
        .map(|(n, _)| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn suggest<'a>(given: &str, names: impl Iterator<Item = &'a str>) -> String {
    names
        .map(|n| (strsim::levenshtein(given, n), n))
        .min_by_key(|(d, _)| *d)
        .filter(|(d, _)| *d <= given.len().max(2) / 2 + 1)
        .map(|(_, n)| format!(" (did you mean `{n}`?)"))
        .unwrap_or_default()
}
