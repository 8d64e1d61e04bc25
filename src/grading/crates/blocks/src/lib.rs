//! The building blocks an exercise may use: what the shipped stubs import,
//! under the same paths (`raystep::ch3_ray_triangle::ray::Ray`), and
//! nothing else of raystep. The exercises crate sees raystep only through
//! this crate, so an exercise cannot call raystep's own solution of
//! itself: `camera.project` (exercise 1.1) and the book's traversal
//! (exercise 3.4) are not here, and neither is the grader. Exercise 3.4's
//! tree, slab test and triangle test are the counted ones of
//! `raystep::grading::counted`, so the work a traversal does is counted
//! where it is done, not inside the lesson's functions.

#![forbid(unsafe_code)]

/// Chapter 1's blocks.
pub mod ch1_projection {
    /// The camera of capstone 1.
    pub mod camera {
        use glam::{Vec2, Vec3};

        /// A pinhole camera, as capstone 1 is handed it: the map from the
        /// world to camera space and the map from the image plane to
        /// raster pixels (not the projection itself, which is exercise 1.1).
        #[derive(Clone, Copy)]
        pub struct Camera<'a> {
            inner: &'a raystep::ch1_projection::camera::Camera,
        }

        impl<'a> Camera<'a> {
            /// The blocks of raystep's camera `inner`.
            pub fn of(inner: &'a raystep::ch1_projection::camera::Camera) -> Camera<'a> {
                Camera { inner }
            }

            /// A world point in camera space (pinhole at the origin,
            /// looking down -z).
            pub fn to_camera(&self, p_world: Vec3) -> Vec3 {
                self.inner.to_camera(p_world)
            }

            /// A point of the image plane z = -1 in raster pixels.
            pub fn raster_from_image_plane(&self, uv: Vec2) -> Vec2 {
                self.inner.raster_from_image_plane(uv)
            }

            /// The picture's width in pixels.
            pub fn width(&self) -> u32 {
                self.inner.width
            }

            /// The picture's height in pixels.
            pub fn height(&self) -> u32 {
                self.inner.height
            }
        }
    }
}

/// Chapter 3's blocks.
pub mod ch3_ray_triangle {
    /// A ray.
    pub mod ray {
        pub use raystep::ch3_ray_triangle::ray::Ray;
    }

    /// The watertight ray-triangle test and its hit: the test is
    /// counted (the grader of exercise 3.4 reads the counts).
    pub mod triangle {
        pub use raystep::grading::counted::{intersect_watertight, Hit};
    }

    /// The tree of exercise 3.4, with its slab test counted.
    pub mod readable_bvh {
        pub use raystep::grading::counted::{Aabb, Node, NodeKind, ReadableBvh};
    }
}

/// Chapter 4's blocks.
pub mod ch4_implicit_surfaces {
    /// The march's settings.
    pub mod march {
        pub use raystep::ch4_implicit_surfaces::march::March;
    }
}

/// Chapter 6's blocks.
pub mod ch6_global_illumination {
    /// The layer slots of exercise 6.6 (the numbers only: the slot of a
    /// bounce count, `slot_of`, is the exercise).
    pub mod layers {
        pub use raystep::ch6_global_illumination::layers::{
            LAYERS_SHOWN, LAYER_SLOTS, SLOT_BEYOND, SLOT_EMITTED,
        };
    }
}

/// Chapter 6's exercises' types, under the paths the stubs name.
pub mod grading {
    /// The exercises' blocks.
    pub mod exercises {
        /// Capstone 6's scene.
        pub mod paths {
            pub use raystep::grading::exercises::paths::{Hit, LightSample, PathScene};
        }

        /// What exercise 6.6 is handed: a path's contributions.
        pub mod bounce_layers {
            pub use raystep::grading::exercises::bounce_layers::{Gathered, How};
        }
    }
}
