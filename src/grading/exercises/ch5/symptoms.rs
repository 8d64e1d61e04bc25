//! The failures chapter 5's checks recognise, each with its hint (cites a
//! lecture slide or a book section by its exact title).

use crate::exercise::Symptom;

/// The Lambertian BRDF without its 1/π (or with it twice).
pub const LAMBERT_PI: Symptom = Symptom { name: "off by π" };
/// The BRDF reflects only above z = 0 (not two-sided).
pub const LAMBERT_ONE_SIDED: Symptom = Symptom {
    name: "nothing below the surface",
};
/// Directions that are not unit vectors on the upper hemisphere.
pub const NOT_ON_HEMISPHERE: Symptom = Symptom {
    name: "not a unit direction on the hemisphere",
};
/// A pdf that is not cos θ / π.
pub const COSINE_PDF: Symptom = Symptom {
    name: "the pdf is not cos θ / π",
};
/// Directions not distributed as cos θ / π.
pub const NOT_COSINE: Symptom = Symptom {
    name: "directions not distributed as cos θ",
};
/// A band of directions, however thin, never drawn.
pub const COSINE_GAP: Symptom = Symptom {
    name: "a band of directions never drawn",
};
/// The inverse-square law missed.
pub const INVERSE_SQUARE: Symptom = Symptom {
    name: "the inverse-square law",
};
/// Light from behind the surface.
pub const POINT_BEHIND: Symptom = Symptom {
    name: "light from behind the surface",
};
/// The Jacobian of exercise 5.4 wrong.
pub const PDF_JACOBIAN: Symptom = Symptom {
    name: "the area-to-solid-angle Jacobian",
};
/// A negative density, or none, when the light is seen from behind.
pub const PDF_SIGN: Symptom = Symptom {
    name: "a density that is negative or missing",
};
/// A solid angle whose sign follows the winding.
pub const SOLID_SIGNED: Symptom = Symptom {
    name: "a signed solid angle",
};
/// A cos θ / r² (or A / r²): right only for a small triangle far away.
pub const SOLID_FAR_LIMIT: Symptom = Symptom {
    name: "the far-away approximation",
};
/// Wrong only beyond a hemisphere's half: atan instead of atan2.
pub const SOLID_ABOVE_PI: Symptom = Symptom {
    name: "a solid angle above π",
};
/// Right near the triangle, wrong for a small triangle far away.
pub const SOLID_PRECISION: Symptom = Symptom {
    name: "precision for a small, far triangle",
};
/// A spot's power wrong only where its edge is soft.
pub const SPOT_BAND: Symptom = Symptom {
    name: "the soft band",
};
/// A spot's power off by the same factor for every cone.
pub const SPOT_FACTOR: Symptom = Symptom {
    name: "off by a constant factor: the sphere",
};
/// A spot's power right for wide cones, wrong for narrow ones.
pub const SPOT_NARROW: Symptom = Symptom {
    name: "precision in a narrow cone",
};

// The capstone's, `direct_light`'s.

/// ρ instead of ρ/π (or π twice).
pub const BRDF_PI: Symptom = Symptom {
    name: "off by π: the BRDF",
};
/// cos θ at the shading point missing or wrong.
pub const COS_SURFACE: Symptom = Symptom {
    name: "the cosine at the shading point",
};
/// The area-to-solid-angle Jacobian (d², cos θl) missing or wrong.
pub const JACOBIAN: Symptom = Symptom {
    name: "the area-to-solid-angle conversion",
};
/// The area A used wrongly.
pub const AREA: Symptom = Symptom {
    name: "the light's area",
};
/// Light from the back face of a one-sided light.
pub const TWO_SIDED: Symptom = Symptom {
    name: "light from the back of a one-sided light",
};
/// Light from below the surface.
pub const BEHIND: Symptom = Symptom {
    name: "light from below the surface",
};
/// Shadows ignored.
pub const NO_SHADOW: Symptom = Symptom { name: "no shadows" };
/// The visibility callback asked about another segment.
pub const WRONG_SEGMENT: Symptom = Symptom {
    name: "the shadow test asks about the wrong segment",
};
/// Off by a constant factor not explained above.
pub const CONSTANT_FACTOR: Symptom = Symptom {
    name: "off by a constant factor",
};

/// Every symptom [`check_direct_light`](super::check_direct_light) can name.
pub const SYMPTOMS: [Symptom; 9] = [
    BRDF_PI,
    COS_SURFACE,
    JACOBIAN,
    AREA,
    TWO_SIDED,
    BEHIND,
    NO_SHADOW,
    WRONG_SEGMENT,
    CONSTANT_FACTOR,
];
