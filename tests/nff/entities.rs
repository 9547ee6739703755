//! Each entity maps onto raybook's scene: the viewpoint, the material, the
//! shapes, NFF's lights, and a TOML scene's defaults for the rest.

use ch03_lambert::{Arrival, arrival};
use raybook::nff;
use raybook::toolkit::scene::{Falloff, Light, Shape, TraceSpec};
use raybook::toolkit::{Color, Vec3};

use super::GOOD;

#[test]
fn every_entity_maps_onto_the_scene() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    assert_eq!(scene.image.background, Vec3::new(0.1, 0.2, 0.3));
    assert_eq!((scene.image.width, scene.image.height), (64, 48));
    assert_eq!(scene.camera.eye, Vec3::new(0.0, -5.0, 1.0));
    // 45° between the centres of the first and last rows of 48: a little
    // more between the edges.
    let half = (22.5f32.to_radians().tan() / (1.0 - 1.0 / 48.0))
        .atan()
        .to_degrees();
    assert!((scene.camera.vfov_degrees - 2.0 * half).abs() < 1e-4);
    let m = &scene.materials[0];
    assert_eq!(m.color, 0.8 * Color::new(1.0, 0.5, 0.25));
    assert_eq!(m.reflectance, Color::splat(0.4));
    assert_eq!((m.specular, m.shininess), (0.4, 30.0));
    assert_eq!((m.transparency, m.ior), (0.5, 1.5));
    // One sphere, the square as two triangles, the patch as one smooth one.
    assert_eq!(scene.objects.len(), 4);
    assert!(matches!(
        scene.objects[0].shape,
        Shape::Sphere { radius: 1.0, .. }
    ));
    assert!(matches!(scene.objects[1].shape, Shape::Triangle { .. }));
    let Shape::SmoothTriangle { normals, .. } = scene.objects[3].shape else {
        panic!("pp makes smooth triangles: {:?}", scene.objects[3]);
    };
    assert_eq!(normals[2], Vec3::new(0.0, 0.6, 0.8));
}

#[test]
fn a_light_without_colour_gets_the_spd_generators_grey_and_no_falloff() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    let Light::Point {
        color,
        intensity,
        falloff,
        ..
    } = scene.lights[0]
    else {
        panic!("NFF lights are point lights");
    };
    // Two lights: 1/√2 each, as the SPD generators write them for POV-Ray.
    assert_eq!(color, Color::splat(0.5f32.sqrt()));
    assert_eq!((intensity, falloff), (1.0, Falloff::None));
    let Light::Point { color, .. } = scene.lights[1] else {
        panic!()
    };
    assert_eq!(color, Color::splat(0.5), "its own colour");
}

#[test]
fn an_nff_light_is_as_bright_near_as_far() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    let light = &scene.lights[0];
    let irradiance = |point: Vec3| match arrival(light, point) {
        Arrival::Incoming(incoming) => incoming.irradiance,
        other => panic!("{other:?}"),
    };
    let (near, far) = (irradiance(Vec3::new(4.0, 3.0, 1.0)), irradiance(Vec3::ZERO));
    assert_eq!(near, far, "1 and 5.4 away");
    assert_eq!(near, Color::splat(0.5f32.sqrt()));
    // The same light with the 1/r² of a TOML scene's point light.
    let mut physical = light.clone();
    if let Light::Point { falloff, .. } = &mut physical {
        *falloff = Falloff::InverseSquare;
    }
    let Arrival::Incoming(far) = arrival(&physical, Vec3::new(4.0, 3.0, -2.0)) else {
        panic!()
    };
    assert!(
        (far.irradiance - near / 16.0).length() < 1e-6,
        "4 away: 1/16"
    );
}

#[test]
fn an_nff_scene_gets_the_defaults_of_a_toml_scene() {
    let scene = nff::parse(GOOD, "good.nff").unwrap();
    assert_eq!(scene.trace, TraceSpec::default());
    assert_eq!(scene.image.samples, 1);
}
