//! NFF import: the SPD scenes load, entities map onto raybook's scene, bad
//! files are refused with the line, and the BVH sees what brute force sees.
//!
//! One test target (`cargo test -p raybook --test nff`), in modules:
//!
//! * `entities`: each NFF entity, light and default as raybook's scene has it;
//! * `errors`: bad files refused with their line, and too large ones before
//!   they are converted;
//! * `cones`: `c` entities, on one line or three, inside out, cut short;
//! * `polygons`: `p` entities cut into compact triangles inside them;
//! * `scenes`: the SPD scenes load, render, and look the same with the BVH
//!   as with brute force.
//!
//! Here: a small scene using every entity, and the helpers that change it.

mod cones;
mod entities;
mod errors;
mod polygons;
mod scenes;

use raybook::nff;
use raybook::scene_files::SceneError;
use raybook::toolkit::scene::Shape;
use raybook::workbench::snapshot::workspace_root;

/// A small scene using every entity raybook reads.
pub(crate) const GOOD: &str = "# a comment
b 0.1 0.2 0.3
v
from 0 -5 1
at 0 0 0
up 0 0 1
angle 45
hither 0.01
resolution 64 48
l 4 3 2
l 1 -4 4 0.5 0.5 0.5
f 1 0.5 0.25 0.8 0.4 30 0.5 1.5
s 0 0 0 1   # a sphere
p 4
-2 -2 -1
2 -2 -1
2 2 -1
-2 2 -1
pp 3
0 0 2 0 0 1
1 0 2 0 0 1
0 1 2 0 0.6 0.8
";

/// A scene of scenes/spd.
pub(crate) fn spd(name: &str) -> std::path::PathBuf {
    workspace_root().join("scenes/spd").join(name)
}

/// The error of a file that must be refused, which names it (printed, to
/// read with `--nocapture`).
pub(crate) fn broken(text: &str) -> SceneError {
    let error = nff::parse(text, "bad.nff").expect_err("must be refused");
    println!("{error}\n");
    assert_eq!(error.file, "bad.nff");
    assert!(error.to_string().starts_with("bad.nff:"), "{error}");
    error
}

/// The good scene with line `line` (1-based) replaced.
pub(crate) fn with_line(line: usize, text: &str) -> String {
    let mut lines: Vec<&str> = GOOD.lines().collect();
    lines[line - 1] = text;
    lines.join("\n")
}

/// The objects of GOOD's material and viewpoint followed by `objects`.
pub(crate) fn shapes_of(objects: &str) -> Vec<Shape> {
    let text = format!("{}{objects}", &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]);
    let scene = nff::parse(&text, "shapes.nff").unwrap_or_else(|e| panic!("{e}"));
    scene.objects.iter().map(|o| o.shape).collect()
}
