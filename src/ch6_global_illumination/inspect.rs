//! Chapter 6's answer to "what happened at this pixel": one path traced
//! from the pixel with
//! [`record_path`](crate::ch6_global_illumination::path_record::record_path),
//! the very sample the render traced, written out vertex by vertex. Its `+`
//! terms add up to what the render added to the pixel for that sample.

use crate::ch6_global_illumination::path_record::{light_name, surface_name, PathEnd, PathRecord};
use crate::core::format::{direction, num, rgb};
use crate::scene::Scene;

/// The table: a block per vertex.
pub fn table_lines(
    scene: &Scene,
    world: &crate::ch5_reflection::world::World,
    r: &PathRecord,
    nee: bool,
) -> Vec<String> {
    let mut out = vec![format!("camera ray {}", direction(r.camera_dir))];
    for (k, v) in r.vertices.iter().enumerate() {
        let material = scene
            .materials
            .get(v.material)
            .map_or("?", |m| m.name.as_str());
        out.push(format!(
            "#{} {} ({material}) t {}",
            k + 1,
            surface_name(scene, v.surface),
            num(v.t)
        ));
        out.push(format!("  β in {}", rgb(v.beta)));
        if let Some(e) = v.emission {
            out.push(format!(
                "  emission Le {} · MIS w {} → +{}",
                rgb(e.le),
                num(e.weight),
                rgb(e.contribution)
            ));
        }
        if let Some(l) = v.light {
            let name = light_name(scene, world, l.light);
            if l.visible {
                out.push(format!(
                    "  NEE light {name}: f {} · Li {} · pdf {} · cos {} · w {} → +{}",
                    rgb(l.f),
                    rgb(l.li),
                    num(l.pdf),
                    num(l.cos),
                    num(l.weight),
                    rgb(l.contribution)
                ));
            } else {
                out.push(format!("  NEE light {name}: in shadow → +0"));
            }
        } else if nee && v.scatter.is_some_and(|s| !s.delta) {
            out.push("  NEE: no light sample reaches this side → +0".into());
        }
        if let Some(s) = v.scatter {
            let how = if s.delta {
                "delta lobe".to_string()
            } else {
                format!("f {} · pdf {} · cos {}", rgb(s.f), num(s.pdf), num(s.cos))
            };
            out.push(format!(
                "  next dir {}: {how} → β {}",
                direction(s.wi),
                rgb(s.beta)
            ));
        }
        if let Some((q, survived)) = v.roulette {
            let verdict = if survived {
                "survived, β / q"
            } else {
                "ended"
            };
            out.push(format!("  roulette q {}: {verdict}", num(q)));
        }
    }
    if let Some((d, e)) = r.escaped {
        out.push(format!(
            "escaped {}: sky Le {} · MIS w {} → +{}",
            direction(d),
            rgb(e.le),
            num(e.weight),
            rgb(e.contribution)
        ));
    }
    let end = match r.end {
        PathEnd::Escaped => "left the scene",
        PathEnd::Roulette => "ended by Russian roulette",
        PathEnd::BounceLimit => "reached the bounce limit",
        PathEnd::Absorbed => "absorbed (no direction carries light)",
    };
    out.push(format!("path {end}"));
    out.push(format!(
        "sum of the + terms: {}",
        rgb(r.contributions_sum())
    ));
    out
}
