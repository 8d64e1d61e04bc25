//! Exercise 6.6, solved: count the surfaces the light scattered at. A
//! light sample at vertex j scattered at vertices 0 to j (k = j); emission
//! found at vertex i ≥ 1 scattered at vertices 0 to i − 1 (k = i − 1);
//! emission found at vertex 0 scattered nowhere (layer E).

use glam::Vec3;
use raystep::ch6_global_illumination::layers::{
    LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
};
use raystep::grading::exercises::bounce_layers::{Gathered, How};

/// The path's light per layer slot.
pub fn bounce_layers(path: &[Gathered]) -> [Vec3; LAYER_SLOTS] {
    let mut layers = [Vec3::ZERO; LAYER_SLOTS];
    for g in path {
        let k = match g.how {
            How::Found if g.vertex == 0 => None,
            How::Found => Some(g.vertex - 1),
            How::LightSample => Some(g.vertex),
        };
        let slot = match k {
            None => SLOT_EMITTED,
            Some(k) if k <= LAYERS_SHOWN => k as usize + 1,
            Some(_) => SLOT_BEYOND,
        };
        let c = g.value * g.weight;
        if c.is_finite() {
            layers[slot] += c;
        }
    }
    layers
}
