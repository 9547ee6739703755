//! A scene of many small spheres in a cube, to measure how loading and
//! rendering grow with the number of objects (see `memory.rs`).

use std::io::{self, Write};

/// Writes a TOML scene of `count` grey spheres of radius 0.01 scattered
/// through the cube [-10, 10]³, seen from 30 units away at 16×12 pixels,
/// under an ambient and a point light. The same `count` gives the same file;
/// each sphere's table is about 90 bytes.
///
/// `cargo run --release -p scene-files --example sphere_cloud -- 2000000 big.toml`
pub fn write_sphere_cloud(mut out: impl Write, count: usize) -> io::Result<()> {
    out.write_all(HEAD.as_bytes())?;
    let mut state = 1u64;
    for _ in 0..count {
        let [x, y, z] = [(); 3].map(|_| 20.0 * unit(&mut state) - 10.0);
        write!(
            out,
            "[[objects]]\ntype = \"sphere\"\ncenter = [{x:.6}, {y:.6}, {z:.6}]\n\
             radius = 0.010000\nmaterial = \"grey\"\n\n"
        )?;
    }
    out.flush()
}

/// Everything but the spheres.
const HEAD: &str = r#"[camera]
eye = [0.0, 0.0, 30.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 16
height = 12

[materials.grey]
color = [0.7, 0.7, 0.7]

[[lights]]
type = "ambient"
color = [0.1, 0.1, 0.1]

[[lights]]
type = "point"
position = [10.0, 10.0, 30.0]
intensity = 400.0

"#;

/// The next number in [0, 1) of a small deterministic sequence (SplitMix64).
fn unit(state: &mut u64) -> f64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) as f64 / (u64::MAX as f64 + 1.0)
}
