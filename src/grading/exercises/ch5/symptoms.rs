//! The failures chapter 5's checks recognise, each with its hint (cites a
//! lecture slide or a book section by its exact title).

use crate::grading::exercise::Symptom;

/// The Lambertian BRDF without its 1/π (or with it twice).
pub const LAMBERT_PI: Symptom = Symptom {
    name: "off by π",
    hint: "slide \"Bidirectional reflectance distribution function\" and book \"BRDFs\": the constant f with ∫ f cos θ dω = ρ over the hemisphere is ρ/π, because ∫ cos θ dω = π.",
};
/// The BRDF reflects only above z = 0 (not two-sided).
pub const LAMBERT_ONE_SIDED: Symptom = Symptom {
    name: "nothing below the surface",
    hint: "book \"BRDFs\": every raystep BRDF is two-sided: it reflects on whichever side the viewer is. Test that ωo and ωi are on the same side (z of the same sign), not that both are above.",
};
/// Directions that are not unit vectors on the upper hemisphere.
pub const NOT_ON_HEMISPHERE: Symptom = Symptom {
    name: "not a unit direction on the hemisphere",
    hint: "book \"Cosine-weighted directions\": a point (x, y) of the unit disk lifts to z = √(1 − x² − y²), so the direction has length 1 and z ≥ 0.",
};
/// A pdf that is not cos θ / π.
pub const COSINE_PDF: Symptom = Symptom {
    name: "the pdf is not cos θ / π",
    hint: "book \"Cosine-weighted directions\": Malley's method gives the density cos θ / π per steradian; the π makes it integrate to 1 over the hemisphere.",
};
/// Directions not distributed as cos θ / π.
pub const NOT_COSINE: Symptom = Symptom {
    name: "directions not distributed as cos θ",
    hint: "book \"Cosine-weighted directions\": the disk point must be uniform by area: the area inside radius r grows as r², so r = √u, not u.",
};
/// The inverse-square law missed.
pub const INVERSE_SQUARE: Symptom = Symptom {
    name: "the inverse-square law",
    hint: "slide \"Radiometry Types of light Isotropic point source\" and book \"Lights\": intensity I spreads over a sphere of area 4π r², so E falls as 1/r² (r², not r).",
};
/// Light from behind the surface.
pub const POINT_BEHIND: Symptom = Symptom {
    name: "light from behind the surface",
    hint: "slide \"Radiometry Lambert's law\": cos θ < 0 means the light is behind the surface: it delivers nothing, so clamp cos θ at 0.",
};
/// The Jacobian of exercise 5.4 wrong.
pub const PDF_JACOBIAN: Symptom = Symptom {
    name: "the area-to-solid-angle Jacobian",
    hint: "slide \"Radiometry Solid angle\": dω = |cos θl| dA / d², so a density per area becomes one per steradian by multiplying by dA/dω = d² / |cos θl|.",
};
/// A negative density, or none, when the light is seen from behind.
pub const PDF_SIGN: Symptom = Symptom {
    name: "a density that is negative or missing",
    hint: "book \"The reflection equation\": a density is never negative: the light's cos θl enters as |cos θl| (which face is lit is the light's business, not the pdf's), and 0 only edge-on.",
};

// The capstone's, `direct_light`'s.

/// ρ instead of ρ/π (or π twice).
pub const BRDF_PI: Symptom = Symptom {
    name: "off by π: the BRDF",
    hint: "slide \"Bidirectional reflectance distribution function\": an ideal diffuse surface of albedo ρ has f = ρ/π, the constant whose integral ∫ f cos θ dω over the hemisphere is ρ.",
};
/// cos θ at the shading point missing or wrong.
pub const COS_SURFACE: Symptom = Symptom {
    name: "the cosine at the shading point",
    hint: "slide \"Radiometry Lambert's law\": light arriving at angle θ to p's normal delivers cos θ = n · wi of its radiance per unit area, with wi the unit direction from p to y.",
};
/// The area-to-solid-angle Jacobian (d², cos θl) missing or wrong.
pub const JACOBIAN: Symptom = Symptom {
    name: "the area-to-solid-angle conversion",
    hint: "slide \"Radiometry Solid angle\": a patch dA at distance d, tilted by θl from the direction to p, covers dω = cos θl dA / d². A point drawn with pdf_A = 1/A per area has pdf_ω = d² / (cos θl · A) per steradian.",
};
/// The area A used wrongly.
pub const AREA: Symptom = Symptom {
    name: "the light's area",
    hint: "book \"The reflection equation\" (light sampling): a point uniform over area A has density pdf_A = 1/A, and the estimate divides by the density: it grows with A.",
};
/// Light from the back face of a one-sided light.
pub const TWO_SIDED: Symptom = Symptom {
    name: "light from the back of a one-sided light",
    hint: "book \"Lights\": an area light emits from its front face only, the side n_light points to: nothing when cos θl = n_light · (−wi) ≤ 0 (not its absolute value).",
};
/// Light from below the surface.
pub const BEHIND: Symptom = Symptom {
    name: "light from below the surface",
    hint: "slide \"Radiometry Lambert's law\": a light below p's surface (cos θ = n · wi ≤ 0) delivers nothing: clamp, do not let the cosine go negative or take its absolute value.",
};
/// Shadows ignored.
pub const NO_SHADOW: Symptom = Symptom {
    name: "no shadows",
    hint: "book \"The reflection equation\": a light sample counts only if nothing blocks the segment from p to y: ask visible(p, y), and return 0 when it says no.",
};
/// The visibility callback asked about another segment.
pub const WRONG_SEGMENT: Symptom = Symptom {
    name: "the shadow test asks about the wrong segment",
    hint: "book \"The reflection equation\": the shadow ray runs from the shading point to the light point: call visible(p, y) with exactly those two points, in that order.",
};
/// Off by a constant factor not explained above.
pub const CONSTANT_FACTOR: Symptom = Symptom {
    name: "off by a constant factor",
    hint: "slide \"Reflection equation Multiple light sources\": one light sample is f · Le · cos θ / pdf_ω = (ρ/π) · Le · cos θ · cos θl / d² · A; compare each factor with yours.",
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
