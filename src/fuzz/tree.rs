//! The structure-aware fuzzer's inputs: a seed scene parsed into a
//! `toml::Value` tree and mutated as a TREE (not as text), an odd OBJ file,
//! an image size, a sample count and a chapter, all drawn by the
//! `arbitrary` crate from bytes that (seed, index) alone decide. Case `i`
//! of seed `s` is the same input on every machine.
//!
//! The tree mutations: a number set to a boundary value (0, -0, tiny,
//! subnormal, huge, NaN and infinities as numbers and as strings, negative,
//! the i64 extremes); every value of one key set to one boundary value; a
//! key or element deleted; a value's type swapped (number, string, array,
//! table); an array grown or shrunk; a key and value from another seed
//! added. The OBJ edits: a byte-order mark, `l` and `p` lines, huge and
//! negative indices, concave polygons, NaN and infinite coordinates, empty
//! and short faces, bad texture and normal indices, collapsed and overlapping triangles
//! repeated, CRLF line endings.

use arbitrary::{Result, Unstructured};
use toml::{Table, Value};

use super::obj::odd_obj;
use super::{Case, Rng, SCENE_SEEDS};

/// One structured input: the scene and OBJ texts, and how it is rendered.
#[derive(Clone, Debug)]
pub struct Structured {
    /// The scene and OBJ texts and the chapter (index into
    /// [`crate::chapters::all`]).
    pub case: Case,
    /// Image width, 1 to 64.
    pub width: u32,
    /// Image height, 1 to 48.
    pub height: u32,
    /// Samples per pixel, 1 to 8.
    pub spp: u32,
    /// What was done to the tree and the OBJ, one phrase each.
    pub edits: Vec<String>,
}

/// Bytes the choices of one case are drawn from.
const ENTROPY: usize = 4096;

// ANCHOR: structured_case
/// Case `index` of the structured run seeded `seed`.
pub fn structured_case(seed: u64, index: u64) -> Structured {
    let mut rng = Rng(seed.rotate_left(17) ^ index.wrapping_mul(0x9fb2_1c65_1e98_df25) ^ 0x5eed);
    let bytes: Vec<u8> = (0..ENTROPY / 8)
        .flat_map(|_| rng.next().to_le_bytes())
        .collect();
    let mut u = Unstructured::new(&bytes);
    // Running out of bytes is not an error for `arbitrary`: every choice
    // then takes its smallest value. So `draw` cannot fail in practice.
    draw(&mut u).unwrap_or_else(|_| draw(&mut Unstructured::new(&[])).expect("empty input"))
}
// ANCHOR_END: structured_case

fn draw(u: &mut Unstructured) -> Result<Structured> {
    let text = SCENE_SEEDS[u.choose_index(SCENE_SEEDS.len())?];
    let mut edits = Vec::new();
    let scene = match text.parse::<Table>() {
        Ok(table) => {
            let mut root = Value::Table(table);
            // Mostly one edit, so that many cases get past the parser.
            let edits_n = if u.ratio(3u8, 4)? {
                1
            } else {
                u.int_in_range(2..=4)?
            };
            for _ in 0..edits_n {
                edits.push(mutate(u, &mut root)?);
            }
            match toml::to_string(&root) {
                Ok(s) => s,
                Err(e) => {
                    edits.push(format!("not serialisable ({e}): the seed as it was"));
                    text.to_string()
                }
            }
        }
        Err(_) => text.to_string(),
    };
    let obj = odd_obj(u, &mut edits)?;
    Ok(Structured {
        case: Case {
            scene,
            obj,
            chapter: u.int_in_range(0..=5)?,
        },
        width: u.int_in_range(1..=64)?,
        height: u.int_in_range(1..=48)?,
        spp: u.int_in_range(1..=8)?,
        edits,
    })
}

/// A step from a node to one of its children.
#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

/// The paths of every node under `v` (the root itself excluded).
fn paths(v: &Value, at: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    let mut visit = |step: Step, child: &Value, at: &mut Vec<Step>| {
        at.push(step);
        out.push(at.clone());
        paths(child, at, out);
        at.pop();
    };
    match v {
        Value::Table(t) => {
            for (k, child) in t {
                visit(Step::Key(k.clone()), child, at);
            }
        }
        Value::Array(a) => {
            for (i, child) in a.iter().enumerate() {
                visit(Step::Index(i), child, at);
            }
        }
        _ => {}
    }
}

fn get<'a>(mut v: &'a Value, path: &[Step]) -> Option<&'a Value> {
    for step in path {
        v = match (v, step) {
            (Value::Table(t), Step::Key(k)) => t.get(k)?,
            (Value::Array(a), Step::Index(i)) => a.get(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

fn get_mut<'a>(mut v: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    for step in path {
        v = match (v, step) {
            (Value::Table(t), Step::Key(k)) => t.get_mut(k)?,
            (Value::Array(a), Step::Index(i)) => a.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

fn same(a: &Step, b: &Step) -> bool {
    match (a, b) {
        (Step::Key(x), Step::Key(y)) => x == y,
        (Step::Index(x), Step::Index(y)) => x == y,
        _ => false,
    }
}

fn name(path: &[Step]) -> String {
    let parts: Vec<String> = path
        .iter()
        .map(|s| match s {
            Step::Key(k) => k.clone(),
            Step::Index(i) => format!("[{i}]"),
        })
        .collect();
    parts.join(".")
}

/// A boundary value for a number.
fn boundary(u: &mut Unstructured) -> Result<Value> {
    use Value::{Float as F, Integer as I, String as S};
    let values = [
        I(0),
        F(-0.0),
        F(1e-7),
        F(1e-30),
        F(f32::MIN_POSITIVE as f64), // the smallest normal f32
        F(1e-40),                    // subnormal as f32
        F(5e-324),                   // subnormal as f64
        F(1e18),
        F(1e20),
        F(3.5e38), // over f32::MAX
        F(1e308),
        F(f64::NAN),
        F(f64::INFINITY),
        F(f64::NEG_INFINITY),
        S("nan".into()),
        S("inf".into()),
        S("-inf".into()),
        I(-1),
        F(-1e30),
        F(-1e-30),
        I(i64::MIN),
        I(i64::MAX),
        I(1 << 32),
        I(-(1 << 31)),
        F(0.5),
        I(1),
        I(2),
        I(5),
        I(6),
        I(7),
        I(65_536),
    ];
    Ok(values[u.choose_index(values.len())?].clone())
}

/// A value of another type holding something of `v`.
fn swapped(u: &mut Unstructured, v: &Value) -> Result<Value> {
    Ok(match (v, u.int_in_range(0..=2u8)?) {
        (Value::Integer(_) | Value::Float(_), 0) => Value::String(v.to_string()),
        (Value::Integer(_) | Value::Float(_), 1) => Value::Array(vec![v.clone()]),
        (Value::String(s), 0) => Value::Integer(s.len() as i64),
        (Value::String(s), 1) => Value::Array(vec![Value::String(s.clone())]),
        (Value::Array(a), 0) => a.first().cloned().unwrap_or(Value::Integer(0)),
        (Value::Array(a), 1) => Value::Table(
            a.iter()
                .enumerate()
                .map(|(i, x)| (i.to_string(), x.clone()))
                .collect(),
        ),
        (Value::Table(t), 0) => Value::Array(t.values().cloned().collect()),
        (Value::Table(_), 1) => Value::String("table".into()),
        (Value::Boolean(b), _) => Value::Integer(*b as i64),
        _ => Value::Table(Table::new()),
    })
}

/// Every (key, value) of every seed scene, for cross-over.
fn donor(u: &mut Unstructured) -> Result<Option<(String, Value)>> {
    let text = SCENE_SEEDS[u.choose_index(SCENE_SEEDS.len())?];
    let Ok(table) = text.parse::<Table>() else {
        return Ok(None);
    };
    let root = Value::Table(table);
    let mut all = Vec::new();
    paths(&root, &mut Vec::new(), &mut all);
    all.retain(|p| matches!(p.last(), Some(Step::Key(_))));
    if all.is_empty() {
        return Ok(None);
    }
    let path = &all[u.choose_index(all.len())?];
    let Some(Step::Key(key)) = path.last() else {
        return Ok(None);
    };
    Ok(get(&root, path).map(|v| (key.clone(), v.clone())))
}

/// One mutation of the tree `root`; says what it did.
fn mutate(u: &mut Unstructured, root: &mut Value) -> Result<String> {
    let mut all = Vec::new();
    paths(root, &mut Vec::new(), &mut all);
    if all.is_empty() {
        return Ok("nothing to mutate".into());
    }
    let numbers: Vec<&Vec<Step>> = all
        .iter()
        .filter(|p| get(root, p).is_some_and(|v| matches!(v, Value::Integer(_) | Value::Float(_))))
        .collect();
    let kind = u.int_in_range(0..=12u8)?;
    let path = match kind {
        0..=4 if !numbers.is_empty() => numbers[u.choose_index(numbers.len())?].clone(),
        _ => all[u.choose_index(all.len())?].clone(),
    };
    let at = name(&path);
    match kind {
        // One number (or, without numbers, any node) at a boundary.
        0..=4 => {
            let b = boundary(u)?;
            let what = format!("{at} = {b}");
            if let Some(v) = get_mut(root, &path) {
                *v = b;
            }
            Ok(what)
        }
        // Every value of one key at one boundary value.
        5 => {
            let Some(Step::Key(key)) = path.iter().rev().find(|s| matches!(s, Step::Key(_))) else {
                return Ok("no key".into());
            };
            let b = boundary(u)?;
            for p in &all {
                if matches!(p.last(), Some(Step::Key(k)) if k == key) {
                    if let Some(v) = get_mut(root, p) {
                        *v = b.clone();
                    }
                }
            }
            Ok(format!("every {key} = {b}"))
        }
        // A key or element deleted.
        6 => {
            let (last, parent) = path.split_last().expect("not the root");
            match (get_mut(root, parent), last) {
                (Some(Value::Table(t)), Step::Key(k)) => {
                    t.remove(k);
                }
                (Some(Value::Array(a)), Step::Index(i)) if *i < a.len() => {
                    a.remove(*i);
                }
                _ => {}
            }
            Ok(format!("{at} deleted"))
        }
        // A type swapped.
        7 => {
            let Some(v) = get_mut(root, &path) else {
                return Ok("gone".into());
            };
            *v = swapped(u, v)?;
            Ok(format!("{at} swapped to {}", v.type_str()))
        }
        // An array grown or shrunk (the innermost array on the path).
        8 | 9 => {
            let arrays: Vec<usize> = (0..=path.len())
                .filter(|&n| matches!(get(root, &path[..n]), Some(Value::Array(_))))
                .collect();
            let Some(&n) = arrays.last() else {
                return Ok(format!("{at}: no array"));
            };
            let grow = kind == 8;
            let count = [1usize, 2, 10, 300][u.choose_index(4)?];
            let b = boundary(u)?;
            if let Some(Value::Array(a)) = get_mut(root, &path[..n]) {
                if grow {
                    let item = a.first().cloned().unwrap_or(b);
                    a.extend(std::iter::repeat_n(item, count));
                } else {
                    a.truncate(a.len().saturating_sub(count));
                }
            }
            let what = if grow { "grown" } else { "shrunk" };
            Ok(format!("{} {what} by {count}", name(&path[..n])))
        }
        // Half the numbers of one table (an object, a light) at
        // boundaries together: a tiny radius with many subdivisions.
        10 => {
            // The innermost table holding the node (or the node itself),
            // never the whole scene.
            let Some(n) = (1..=path.len())
                .rev()
                .find(|&n| matches!(get(root, &path[..n]), Some(Value::Table(_))))
            else {
                return Ok(format!("{at}: in no table"));
            };
            let inside: Vec<&Vec<Step>> = numbers
                .iter()
                .copied()
                .filter(|p| p.len() > n && p[..n].iter().zip(&path[..n]).all(|(a, b)| same(a, b)))
                .collect();
            let mut what = Vec::new();
            for p in inside {
                if u.ratio(1u8, 2)? {
                    let b = boundary(u)?;
                    what.push(format!("{} = {b}", name(p)));
                    if let Some(v) = get_mut(root, p) {
                        *v = b;
                    }
                }
            }
            Ok(format!("together: {}", what.join(", ")))
        }
        // A key and value from another seed added to a table on the path.
        _ => {
            let Some((key, value)) = donor(u)? else {
                return Ok("no donor".into());
            };
            let n = (0..path.len())
                .rev()
                .find(|&n| matches!(get(root, &path[..n]), Some(Value::Table(_))))
                .unwrap_or(0);
            let what = format!("{key} added under `{}`", name(&path[..n]));
            if let Some(Value::Table(t)) = get_mut(root, &path[..n]) {
                t.insert(key, value);
            }
            Ok(what)
        }
    }
}
