//! Seeded random scenes, rendered by each chapter's own render path: the
//! pictures that a chapter's exercises draw together.

use crate::Picture;
use crate::draw::{Rng, chance, number, point, rng_for, unit, whole};
use ch01_rays::scene_files;
use ch01_rays::toolkit::{Image, Scene, Vec3};

/// How many scenes a chapter is probed with, and their size: small, as the
/// snapshot tests render (the tolerance is `workbench::compare`'s).
pub const SCENES: usize = 3;
pub const WIDTH: u32 = 64;
pub const HEIGHT: u32 = 48;

/// A scene with a camera and nothing else.
pub const EMPTY: &str = "[camera]\neye = [0.0, 0.0, 5.0]\nlook_at = [0.0, 0.0, 0.0]\n\
                         up = [0.0, 1.0, 0.0]\nvfov = 50.0\n[image]\nwidth = 8\nheight = 8\n";

/// A scene from text the probe wrote (it is always valid).
pub fn parse(text: &str) -> Scene {
    scene_files::parse(text, "probe.toml")
        .unwrap_or_else(|e| panic!("the probe wrote a bad scene: {e}\n{text}"))
}

/// The chapters whose scenes this build renders.
pub fn chapters() -> Vec<&'static str> {
    let built = [
        ("01-rays", cfg!(feature = "ch01")),
        ("02-hits", cfg!(feature = "ch02")),
        ("03-lambert", cfg!(feature = "ch03")),
        ("04-shadows", cfg!(feature = "ch04")),
        ("05-reflection", cfg!(feature = "ch05")),
        ("06-refraction", cfg!(feature = "ch06")),
        ("07-termination", cfg!(feature = "ch07")),
    ];
    built
        .into_iter()
        .filter(|(_, on)| *on)
        .map(|(c, _)| c)
        .collect()
}

/// The seeded scenes of `chapter`.
pub fn render(chapter: &str, seed: u64) -> Vec<Picture> {
    (0..SCENES)
        .filter_map(|i| {
            let mut rng = rng_for(seed, &format!("{chapter} scene {i}"));
            let (name, uses, image) = draw(chapter, i, &mut rng)?;
            let rgb = image.to_rgb8().into_raw();
            Some(Picture {
                name: format!("{chapter} seeded scene {}{name}", i + 1),
                uses: uses.iter().map(|s| s.to_string()).collect(),
                width: WIDTH,
                height: HEIGHT,
                rgb,
            })
        })
        .collect()
}

/// Writes each picture as a PNG into `folder`, named after it, to look at.
pub fn save_pngs(pictures: &[Picture], folder: &std::path::Path) -> Result<(), String> {
    std::fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    for picture in pictures {
        let image = ::image::RgbImage::from_raw(picture.width, picture.height, picture.rgb.clone());
        let image = image.ok_or("a picture of the wrong size")?;
        let name = picture.name.replace(' ', "-").replace(['(', ')'], "");
        let path = folder.join(format!("{name}.png"));
        ch01_rays::toolkit::image::write_atomically(
            &path,
            &ch01_rays::toolkit::image::encode_png(&image),
        )
        .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

const CH01: [&str; 3] = ["ch01-at", "ch01-frame", "ch01-ray-through"];
const CH02: [&str; 5] = [
    "ch02-closest",
    "ch02-plane",
    "ch02-sphere",
    "ch02-nearest",
    "ch02-triangle",
];
const CH03: [&str; 3] = ["ch03-lambert", "ch03-light-loop", "ch03-spot"];
const CH04: [&str; 4] = [
    "ch04-shadow-ray",
    "ch04-any-hit",
    "ch04-light-is-free",
    "ch04-offset",
];
const CH05: [&str; 5] = [
    "ch05-trace",
    "ch05-recursion",
    "ch05-reflect",
    "ch05-mirror-ray",
    "ch05-highlight",
];
const CH06: [&str; 3] = ["ch06-refract", "ch06-schlick", "ch06-split"];
const CH07: [&str; 2] = ["ch07-below-threshold", "ch07-may-trace"];

/// The exercises of the chapters up to chapter `number`: what a scene of
/// that chapter draws with.
fn up_to(number: usize) -> Vec<&'static str> {
    let all: [&[&'static str]; 7] = [&CH01, &CH02, &CH03, &CH04, &CH05, &CH06, &CH07];
    all[..number].concat()
}

/// The `i`th scene of `chapter`: its name's tail, the exercises that draw
/// it, its picture.
#[allow(unused_variables)]
fn draw(chapter: &str, i: usize, rng: &mut Rng) -> Option<(String, Vec<&'static str>, Image)> {
    let camera = camera(rng);
    match chapter {
        "01-rays" => {
            let scene = parse(&format!("{camera}{}", image(rng)));
            let uses = up_to(1)[1..].to_vec();
            Some((String::new(), uses, ch01_rays::render_sky(&scene, || {}).0))
        }
        #[cfg(feature = "ch02")]
        "02-hits" => {
            use ch02_hits::{Method, View};
            let scene = parse(&format!("{camera}{}{}", image(rng), objects(rng)));
            let (view, name) = [(View::Flat, "flat"), (View::Normals, "normals")][i % 2];
            let uses = up_to(2);
            let picture = ch02_hits::render_hits(&scene, view, Method::Lecture, || {}).0;
            Some((format!(" ({name})"), uses, picture))
        }
        #[cfg(feature = "ch03")]
        "03-lambert" => {
            let text = format!("{camera}{}{}{}", image(rng), objects(rng), lights(rng));
            let scene = parse(&text);
            Some((
                String::new(),
                up_to(3),
                ch03_lambert::render_lambert(&scene, || {}).0,
            ))
        }
        #[cfg(feature = "ch04")]
        "04-shadows" => {
            let scene = parse(&lit_scene(rng, &camera, 4));
            let start = ch04_shadows::ShadowStart::Offset;
            let picture = ch04_shadows::render_shadows(&scene, start, || {}).0;
            Some((String::new(), up_to(4), picture))
        }
        #[cfg(feature = "ch05")]
        "05-reflection" => {
            let scene = parse(&lit_scene(rng, &camera, 5));
            let picture = ch05_reflection::render_mirrors(&scene, || {}).0;
            Some((String::new(), up_to(5), picture))
        }
        #[cfg(feature = "ch06")]
        "06-refraction" => {
            let scene = parse(&lit_scene(rng, &camera, 6));
            let picture = ch06_refraction::render_glass(&scene, || {}).0;
            Some((String::new(), up_to(6), picture))
        }
        #[cfg(feature = "ch07")]
        "07-termination" => {
            let scene = parse(&lit_scene(rng, &camera, 7));
            let criteria = ch07_termination::Termination::of(&scene);
            let picture = ch07_termination::render_terminated(&scene, criteria, || {}).0;
            Some((String::new(), up_to(7), picture))
        }
        _ => None,
    }
}

/// A direction turned to point upwards (above the floor).
fn above(v: Vec3) -> Vec3 {
    Vec3::new(v.x, v.y.abs() + 0.4, v.z).normalize()
}

fn vector(v: Vec3) -> String {
    format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z)
}

/// A camera a few units from the origin, looking near it.
fn camera(rng: &mut Rng) -> String {
    let eye = above(unit(rng)) * number(rng, 4.0, 6.0);
    let look_at = point(rng, 1.0);
    let up = if chance(rng, 0.5) { Vec3::Y } else { unit(rng) };
    let view = (look_at - eye).normalize();
    let up = if view.dot(up).abs() > 0.9 {
        view.cross(Vec3::X).normalize()
    } else {
        up
    };
    format!(
        "[camera]\neye = {}\nlook_at = {}\nup = {}\nvfov = {:?}\n",
        vector(eye),
        vector(look_at),
        vector(up),
        number(rng, 30.0, 70.0)
    )
}

fn image(rng: &mut Rng) -> String {
    let background = Vec3::new(
        number(rng, 0.0, 0.3),
        number(rng, 0.0, 0.3),
        number(rng, 0.0, 0.3),
    );
    format!(
        "[image]\nwidth = {WIDTH}\nheight = {HEIGHT}\nbackground = {}\n",
        vector(background)
    )
}

/// Three materials and a few spheres, triangles and a plane near the origin.
#[allow(dead_code)]
fn objects(rng: &mut Rng) -> String {
    let mut text = String::new();
    for m in 0..3 {
        text += &matte(rng, m);
    }
    text + &shapes(rng, false)
}

/// The table of material `m{m}`, with a colour of its own.
#[allow(dead_code)]
fn matte(rng: &mut Rng, m: u32) -> String {
    let color = Vec3::new(
        number(rng, 0.1, 1.0),
        number(rng, 0.1, 1.0),
        number(rng, 0.1, 1.0),
    );
    format!("[materials.m{m}]\ncolor = {}\n", vector(color))
}

/// A plane, a few spheres and triangles near the origin, of the materials
/// m0 to m2; with `shadowless`, one in five casts no shadow.
#[allow(dead_code)]
fn shapes(rng: &mut Rng, shadowless: bool) -> String {
    let mut text = String::new();
    let mut object = |rng: &mut Rng, kind: &str, fields: String| {
        let m = whole(rng, 0, 2);
        let shadows = match shadowless && chance(rng, 0.2) {
            true => "shadows = false\n",
            false => "",
        };
        text += &format!("[[objects]]\ntype = \"{kind}\"\n{fields}material = \"m{m}\"\n{shadows}");
    };
    let normal = (Vec3::Y + 0.3 * unit(rng)).normalize();
    let fields = format!(
        "normal = {}\noffset = {:?}\n",
        vector(normal),
        number(rng, 2.0, 3.0)
    );
    object(rng, "plane", fields);
    for _ in 0..whole(rng, 2, 4) {
        let (center, radius) = (point(rng, 1.5), number(rng, 0.4, 1.2));
        let fields = format!("center = {}\nradius = {radius:?}\n", vector(center));
        object(rng, "sphere", fields);
    }
    for _ in 0..whole(rng, 1, 3) {
        let p0 = point(rng, 2.0);
        let (p1, p2) = (p0 + point(rng, 1.5), p0 + point(rng, 1.5));
        if (p1 - p0).cross(p2 - p0).length() < 0.2 {
            continue;
        }
        let fields = format!(
            "vertices = [{}, {}, {}]\n",
            vector(p0),
            vector(p1),
            vector(p2)
        );
        object(rng, "triangle", fields);
    }
    text
}

/// An ambient light, a point light and a spot light aimed near the origin.
#[allow(dead_code)]
fn lights(rng: &mut Rng) -> String {
    let ambient = number(rng, 0.02, 0.15);
    let point_at = above(unit(rng)) * number(rng, 4.0, 7.0);
    let spot_at = above(unit(rng)) * number(rng, 4.0, 7.0);
    let axis = (point(rng, 1.0) - spot_at).normalize();
    let inner = number(rng, 5.0, 25.0);
    format!(
        "[[lights]]\ntype = \"ambient\"\ncolor = [{ambient:?}, {ambient:?}, {ambient:?}]\n\
         [[lights]]\ntype = \"point\"\nposition = {}\ncolor = [1.0, 1.0, 1.0]\nintensity = {:?}\n\
         [[lights]]\ntype = \"spot\"\nposition = {}\ndirection = {}\ncolor = [1.0, 0.9, 0.8]\n\
         intensity = {:?}\ninner_angle = {inner:?}\nouter_angle = {:?}\n",
        vector(point_at),
        number(rng, 10.0, 40.0),
        vector(spot_at),
        vector(axis),
        number(rng, 20.0, 50.0),
        inner + number(rng, 1.0, 15.0),
    )
}

/// A scene of chapter `number` (4 to 7): chapter 3's objects and lights,
/// then what the chapter adds. Chapter 4: objects and lights that cast no
/// shadow. Chapter 5: mirrors, and shiny materials. Chapter 6: a glass.
/// Chapter 7: a weight threshold high enough to end paths.
#[allow(dead_code)]
fn lit_scene(rng: &mut Rng, camera: &str, chapter: u32) -> String {
    let mut text = format!("{camera}{}", image(rng));
    let max_depth = whole(rng, 2, 5);
    let min_weight = match chapter {
        7 => number(rng, 0.05, 0.3),
        _ => 0.0,
    };
    text += &format!("[trace]\nmax_depth = {max_depth}\nmin_weight = {min_weight:?}\n");
    for m in 0..3 {
        text += &matte(rng, m);
        if chapter >= 5 && m > 0 {
            let reflectance = number(rng, 0.1, 0.8);
            text += &format!(
                "reflectance = [{reflectance:?}, {reflectance:?}, {reflectance:?}]\n\
                 specular = {:?}\nshininess = {:?}\n",
                number(rng, 0.1, 0.9),
                number(rng, 5.0, 120.0)
            );
        }
        if chapter >= 6 && m == 2 {
            text += &format!(
                "transparency = {:?}\nior = {:?}\nfresnel = {}\n",
                number(rng, 0.5, 0.95),
                number(rng, 1.2, 2.0),
                chance(rng, 0.7)
            );
        }
    }
    text += &shapes(rng, true);
    text += &lights(rng);
    if chance(rng, 0.5) {
        // A second point light that casts no shadow.
        let at = above(unit(rng)) * number(rng, 4.0, 7.0);
        text += &format!(
            "[[lights]]\ntype = \"point\"\nposition = {}\nintensity = {:?}\nshadows = false\n",
            vector(at),
            number(rng, 5.0, 20.0)
        );
    }
    text
}
