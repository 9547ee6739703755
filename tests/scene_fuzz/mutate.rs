//! Mutations of scene files: the seeds (the repository's own scenes and
//! meshes), the tokens likely to break something, and how a mutation
//! changes a text.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use raybook::workbench::snapshot::workspace_root;

use super::common;

/// Every scene file of the repository, as mutation seeds.
pub fn seeds() -> Vec<String> {
    (common::chapter_scene_files().iter())
        .map(|path| std::fs::read_to_string(path).unwrap())
        .collect()
}

/// Tokens that are likely to break something when dropped into a scene.
pub const TOKENS: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "-1",
    "0",
    "0.0",
    "1e39",
    "1e-45",
    "16385",
    "[",
    "]",
    "\"",
    "=",
    ",",
    "\n",
    "[[objects]]",
    "type = \"sphere\"",
    "[0, 0, 0]",
    "[1, 2]",
    "[1, 2, 3, 4]",
    "material = \"nope\"",
    "true",
    "#",
    "{",
    "}",
    ".",
    "é",
    "\u{0}",
];

/// The small SPD scenes (NFF) of the repository, as mutation seeds.
pub fn nff_seeds() -> Vec<String> {
    ["balls-1.nff", "balls-2.nff", "mount-3.nff", "tetra-3.nff"]
        .map(|name| std::fs::read_to_string(workspace_root().join("scenes/spd").join(name)))
        .map(Result::unwrap)
        .to_vec()
}

/// NFF's tokens that are likely to break something.
pub const NFF_TOKENS: &[&str] = &[
    "nan",
    "inf",
    "-1",
    "0",
    "0 0 0",
    "1e39",
    "1e-45",
    "16385",
    "3.5",
    "\n",
    "#",
    "é",
    "\u{0}",
    "\nv\n",
    "\np 3\n",
    "\npp 3\n",
    "\ns 0 0 0 1\n",
    "\nf 1 1 1 1 0 1 0 1\n",
    "\nl 1 1 1\n",
    "\nc\n",
    "\nresolution 1 1\n",
    "\nangle 179.99999\n",
    "\nup 0 0 0\n",
];

/// A small OBJ mesh with what the workbook's reader reads: groups, texture
/// coordinates and normals, every form of corner, relative indices, a
/// quad, a pentagon, points and lines.
const SMALL_OBJ: &str = "# a small mesh\no square\ng front\nusemtl any\n\
    v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0.2\nvt 0 0\nvt 1 0\nvt 1 1\n\
    vn 0 0 1\nvn 0 0.1 1\ns 1\nf 1 2 3 4\nf 1/1 2/2 3/3\nf -5/1/1 -4/2/1 -3/3/2\n\
    f 1//1 2//1 3//2 5//2 4//1\nl 1 2\np 3\n";

/// OBJ meshes as mutation seeds: chapter 8's torus (4096 smooth triangles),
/// the small mesh, and the small mesh as Windows writes it (CRLF, with a
/// byte order mark).
pub fn obj_seeds() -> Vec<String> {
    let torus = workspace_root().join("chapters/08-bvh/scenes/torus.obj");
    let windows = format!("\u{FEFF}{}", SMALL_OBJ.replace('\n', "\r\n"));
    vec![
        std::fs::read_to_string(torus).unwrap(),
        SMALL_OBJ.into(),
        windows,
    ]
}

/// OBJ's tokens that are likely to break something.
pub const OBJ_TOKENS: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "-1",
    "0",
    "-0",
    "1e39",
    "1e-45",
    "9223372036854775807",
    "-9223372036854775808",
    "/",
    "//",
    " ",
    "\n",
    "\r\n",
    "\r",
    "\u{FEFF}",
    "\u{0}",
    "\u{7f}",
    "#",
    "\\\n",
    "é",
    "\nv 0 0 0\n",
    "\nv 1e-30 1e-30 1e-30\n",
    "\nvn 0 0 0\n",
    "\nvt 0 0\n",
    "\nf 1 2 3\n",
    "\nf -1 -2 -3\n",
    "\nf 1/1/1 2/2/2 3/3/3\n",
    "\nf 1 2\n",
    "\nf 1 1 1\n",
    "\nf 99999999999 1 2\n",
    "\nmtllib gone.mtl\n",
    "\nl 1 2\n",
    "\ng\n",
];

/// A change at a place in a text (any number: taken modulo the text's
/// length) with a token (modulo the tokens).
#[derive(Debug, Clone)]
pub enum Mutation {
    Insert(usize, usize),
    Delete(usize, usize),
    Replace(usize, usize, usize),
    /// A token inserted at the start of the line of the place, followed by
    /// a line end: a line of its own, so the lines around it stay whole
    /// (what a file that is well formed, but odd, looks like).
    InsertLine(usize, usize),
}

pub fn apply(text: &str, m: &Mutation) -> String {
    apply_with(text, m, TOKENS)
}

pub fn apply_with(text: &str, m: &Mutation, tokens: &[&str]) -> String {
    let cut = |i: usize| {
        let mut i = i % (text.len() + 1);
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    match *m {
        Mutation::Insert(at, token) => {
            let at = cut(at);
            format!(
                "{}{}{}",
                &text[..at],
                tokens[token % tokens.len()],
                &text[at..]
            )
        }
        Mutation::Delete(at, len) => {
            let (a, b) = (cut(at), cut(at.saturating_add(len % 40)));
            let (a, b) = (a.min(b), a.max(b));
            format!("{}{}", &text[..a], &text[b..])
        }
        Mutation::Replace(at, len, token) => {
            let (a, b) = (cut(at), cut(at.saturating_add(len % 8)));
            let (a, b) = (a.min(b), a.max(b));
            format!(
                "{}{}{}",
                &text[..a],
                tokens[token % tokens.len()],
                &text[b..]
            )
        }
        Mutation::InsertLine(at, token) => {
            let at = text[..cut(at)].rfind('\n').map_or(0, |i| i + 1);
            let token = tokens[token % tokens.len()].trim_matches('\n');
            format!("{}{token}\n{}", &text[..at], &text[at..])
        }
    }
}

pub fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), any::<usize>()).prop_map(|(a, t)| Mutation::Insert(a, t)),
        (any::<usize>(), any::<usize>()).prop_map(|(a, l)| Mutation::Delete(a, l)),
        (any::<usize>(), any::<usize>(), any::<usize>())
            .prop_map(|(a, l, t)| Mutation::Replace(a, l, t)),
        (any::<usize>(), any::<usize>()).prop_map(|(a, t)| Mutation::InsertLine(a, t)),
    ]
}

/// The seed `seed` (any number: taken modulo the seeds) with `mutations`
/// made in turn, with `tokens`.
pub fn mutated(seeds: &[String], seed: usize, mutations: &[Mutation], tokens: &[&str]) -> String {
    let mut text = seeds[seed % seeds.len()].clone();
    for m in mutations {
        text = apply_with(&text, m, tokens);
    }
    text
}

/// A folder of its own for one case, under the tests' temporary folder:
/// removed when dropped.
pub struct CaseDir(pub PathBuf);

impl CaseDir {
    pub fn new() -> CaseDir {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("scene_fuzz-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        CaseDir(dir)
    }

    /// Writes `obj` as mesh.obj and a scene that names it as scene.toml;
    /// the scene's path.
    pub fn scene_with_mesh(&self, obj: &str) -> PathBuf {
        std::fs::write(self.0.join("mesh.obj"), obj).unwrap();
        let scene = self.0.join("scene.toml");
        std::fs::write(&scene, MESH_SCENE).unwrap();
        scene
    }
}

impl Drop for CaseDir {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

/// A scene of one mesh, `mesh.obj` beside it, seen from where chapter 8's
/// torus fills the picture.
const MESH_SCENE: &str = "[camera]\neye = [0.0, 2.2, 4.5]\nlook_at = [0.0, 0.6, 0.0]\n\
    up = [0.0, 1.0, 0.0]\nvfov = 40.0\n\n[image]\nwidth = 8\nheight = 6\n\n\
    [materials.copper]\ncolor = [0.75, 0.4, 0.25]\nspecular = 0.6\n\n\
    [[lights]]\ntype = \"point\"\nposition = [3.0, 5.0, 4.0]\nintensity = 45.0\n\n\
    [[objects]]\ntype = \"mesh\"\npath = \"mesh.obj\"\nmaterial = \"copper\"\n";
