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
    let mut all = vec!["01-rays"];
    #[cfg(feature = "ch02")]
    all.push("02-hits");
    #[cfg(feature = "ch03")]
    all.push("03-lambert");
    all
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

/// The `i`th scene of `chapter`: its name's tail, the exercises that draw
/// it, its picture.
#[allow(unused_variables)]
fn draw(chapter: &str, i: usize, rng: &mut Rng) -> Option<(String, Vec<&'static str>, Image)> {
    let camera = camera(rng);
    match chapter {
        "01-rays" => {
            let scene = parse(&format!("{camera}{}", image(rng)));
            let uses = CH01[1..].to_vec();
            Some((String::new(), uses, ch01_rays::render_sky(&scene, || {}).0))
        }
        #[cfg(feature = "ch02")]
        "02-hits" => {
            use ch02_hits::{Method, View};
            let scene = parse(&format!("{camera}{}{}", image(rng), objects(rng)));
            let (view, name) = [(View::Flat, "flat"), (View::Normals, "normals")][i % 2];
            let uses = [CH01.as_slice(), &CH02].concat();
            let picture = ch02_hits::render_hits(&scene, view, Method::Lecture, || {}).0;
            Some((format!(" ({name})"), uses, picture))
        }
        #[cfg(feature = "ch03")]
        "03-lambert" => {
            let text = format!("{camera}{}{}{}", image(rng), objects(rng), lights(rng));
            let scene = parse(&text);
            let ch03 = ["ch03-lambert", "ch03-light-loop", "ch03-spot"];
            let uses = [CH01.as_slice(), &CH02, &ch03].concat();
            Some((
                String::new(),
                uses,
                ch03_lambert::render_lambert(&scene, || {}).0,
            ))
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
        let color = Vec3::new(
            number(rng, 0.1, 1.0),
            number(rng, 0.1, 1.0),
            number(rng, 0.1, 1.0),
        );
        text += &format!("[materials.m{m}]\ncolor = {}\n", vector(color));
    }
    let object = |kind: &str, fields: String, m: u32| {
        format!("[[objects]]\ntype = \"{kind}\"\n{fields}material = \"m{m}\"\n")
    };
    text += &object(
        "plane",
        format!(
            "normal = {}\noffset = {:?}\n",
            vector((Vec3::Y + 0.3 * unit(rng)).normalize()),
            number(rng, 2.0, 3.0)
        ),
        whole(rng, 0, 2),
    );
    for _ in 0..whole(rng, 2, 4) {
        let (center, radius) = (point(rng, 1.5), number(rng, 0.4, 1.2));
        let fields = format!("center = {}\nradius = {radius:?}\n", vector(center));
        text += &object("sphere", fields, whole(rng, 0, 2));
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
        text += &object("triangle", fields, whole(rng, 0, 2));
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
