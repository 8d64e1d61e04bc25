//! Checks in the units the renderer computes in. A scene file holds f64
//! numbers, the renderer f32: a value is accepted only if it is finite *as
//! f32* and inside a bound that keeps the arithmetic built on it finite
//! (positions are squared, light is multiplied by reflectances and divided
//! by densities). Every message names the bound.

use glam::DVec3;

use super::file::LightSection;

/// The largest coordinate (or length) a scene may use: the watertight
/// triangle test multiplies three coordinate differences in f32, and with
/// differences up to 2e12 its sums stay below 1e38, under f32's 3.4e38
/// (at 1e13 they overflowed, and chapter 4 drew hits at t = ∞ as NaN).
pub const MAX_COORDINATE: f64 = 1e12;
/// The largest light value (emission, radiance, intensity, irradiance):
/// leaves f32 headroom for the products and divisions of shading.
pub const MAX_LIGHT: f64 = 1e20;
/// The smallest length a scene may use: below it f32 has no normal numbers.
pub const MIN_LENGTH: f64 = f32::MIN_POSITIVE as f64;

/// Every value finite and within ±`max`: the reason otherwise.
pub fn within(values: &[f64], max: f64) -> Result<(), String> {
    match values.iter().find(|v| !(v.is_finite() && v.abs() <= max)) {
        None => Ok(()),
        Some(v) => Err(format!(
            "must be finite numbers within ±{max:e} (the renderer computes in f32), got {values:?} ({v} is not)"
        )),
    }
}

/// A position: finite, within ±[`MAX_COORDINATE`].
pub fn position(values: &[f64]) -> Result<(), String> {
    within(values, MAX_COORDINATE)
}

/// A light value: non-negative, at most [`MAX_LIGHT`].
pub fn light(values: &[f64]) -> Result<(), String> {
    within(values, MAX_LIGHT)?;
    if values.iter().any(|v| *v < 0.0) {
        return Err(format!(
            "must not be negative (light cannot be taken away), got {values:?}"
        ));
    }
    Ok(())
}

/// A direction: finite and not zero, also once rounded to f32.
pub fn direction(values: &[f64; 3]) -> Result<(), String> {
    within(values, MAX_COORDINATE)?;
    if DVec3::from(*values).as_vec3().try_normalize().is_none() {
        return Err(direction_problem(values));
    }
    Ok(())
}

/// Why `values` has no direction: the zero vector, or a vector too short
/// for f32 to normalise (its squared length underflows), said as such.
pub fn direction_problem(values: &[f64; 3]) -> String {
    if values.iter().all(|v| *v == 0.0) {
        return format!("must not be the zero vector, got {values:?}");
    }
    let length = DVec3::from(*values).length();
    format!(
        "is too short to give a direction in f32 (length {length:e}; a direction must be \
         long enough that its squared length does not underflow in f32: about 1e-22 or \
         more), got {values:?}"
    )
}

/// The key (relative to `lights[i]`) and reason of the first problem with
/// a light, if any.
pub fn check_light(l: &LightSection) -> Result<(), (&'static str, String)> {
    let at = |key: &'static str| move |why: String| (key, why);
    match l {
        LightSection::Point {
            position: p,
            intensity,
        } => {
            position(p).map_err(at("position"))?;
            light(intensity).map_err(at("intensity"))
        }
        LightSection::Directional {
            direction: d,
            irradiance,
        } => {
            direction(d).map_err(at("direction"))?;
            light(irradiance).map_err(at("irradiance"))
        }
        LightSection::Spot {
            position: p,
            direction: d,
            intensity,
            cone_degrees,
            falloff_degrees,
        } => {
            position(p).map_err(at("position"))?;
            direction(d).map_err(at("direction"))?;
            light(intensity).map_err(at("intensity"))?;
            let cone = *cone_degrees;
            if !(cone.is_finite() && cone > 0.0 && cone <= 180.0) {
                return Err((
                    "cone_degrees",
                    format!("must be a half-angle in (0, 180] degrees, got {cone}"),
                ));
            }
            let falloff = *falloff_degrees;
            if !(falloff.is_finite() && (0.0..=cone).contains(&falloff)) {
                return Err((
                    "falloff_degrees",
                    format!(
                        "must lie in [0, cone_degrees] = [0, {cone}] (the soft edge is inside the cone), got {falloff}"
                    ),
                ));
            }
            Ok(())
        }
        LightSection::Environment { radiance } => light(radiance).map_err(at("radiance")),
        LightSection::Sky {
            zenith,
            horizon,
            ground,
        } => {
            light(zenith).map_err(at("zenith"))?;
            light(horizon).map_err(at("horizon"))?;
            light(ground).map_err(at("ground"))
        }
    }
}
