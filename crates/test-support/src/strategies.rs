//! proptest strategies for the scenes' shapes.

use ch00_toolkit::Vec3;
use ch00_toolkit::scene::Shape;
use proptest::prelude::*;

/// A point in the cube [−4, 4)³.
pub fn point() -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(-4.0f32..4.0).prop_map(Vec3::from)
}

/// The cone (or cylinder) of these ends, if the scene files would accept
/// it with room to spare: an axis longer than 0.1 and a radius above 0.05
/// at one end at least.
pub fn usable_cone(
    (base, apex): (Vec3, Vec3),
    (base_radius, apex_radius): (f32, f32),
    inside_out: bool,
) -> Option<Shape> {
    let usable = base.distance(apex) > 0.1 && base_radius.max(apex_radius) > 0.05;
    usable.then_some(Shape::Cone {
        base,
        base_radius,
        apex,
        apex_radius,
        inside_out,
    })
}

/// A cone or cylinder, pointed at either end or not.
pub fn cone() -> impl Strategy<Value = Shape> {
    let radius = || prop_oneof![Just(0.0f32), 0.05f32..1.0];
    (point(), point(), radius(), radius(), any::<bool>()).prop_filter_map(
        "no axis or no radius",
        |(base, apex, base_radius, apex_radius, inside_out)| {
            usable_cone((base, apex), (base_radius, apex_radius), inside_out)
        },
    )
}
