//! `workbook verify CHAPTER IMAGE.png`: checks a picture made by a student's
//! own tracer, in any language, against the chapter's reference picture.
//!
//! The reference is the chapter's default scene rendered at 160×120 (the
//! snapshot size); the comparison is the snapshot tolerance of every test.
//! A failing picture is diagnosed ([`diagnose`]): the usual mistake that
//! explains it is named with its fix, or else the region where it differs,
//! the objects the reference shows there ([`objects`]) and the lights that
//! light it ([`lights`]).
//!
//! `workbook verify --tree CHAPTER X,Y MINE.json` checks one pixel's ray
//! tree instead, ray by ray ([`tree`]).

mod advice;
pub mod diagnose;
pub mod lights;
pub mod objects;
pub mod region;
mod runs;
pub mod tree;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use include_dir::{Dir, include_dir};

use crate::toolkit::image::{encode_png, write_atomically};
use crate::workbench::chapters::{self, ChapterEntry, VerifyReference};
use crate::workbench::compare::{Tolerance, Verdict, compare, diff_image};
pub use diagnose::{Corner, Diagnosis, Mistake, Swap, diagnose};
pub use lights::LightMap;
pub use objects::{ObjectMap, ObjectName, shape_name};

/// A chapter's reference picture for its default scene.
#[derive(Debug, Clone, Copy)]
pub struct Reference {
    /// The chapter, as chapters/chapters.toml lists it.
    pub chapter: &'static ChapterEntry,
    /// The reference picture, `snapshots/<folder>/<snapshot>.snap.png`.
    pub png: &'static [u8],
    /// Which object each pixel of the reference shows,
    /// `snapshots/<folder>/<snapshot>.objects.txt`, if there is one.
    pub objects: Option<&'static str>,
    /// Which lights light each pixel of the reference,
    /// `snapshots/<folder>/<snapshot>.lights.txt`, if there is one (chapter 3 on).
    pub lights: Option<&'static str>,
}

/// The reference pictures, built into the binary so that it works from
/// anywhere; which picture is a chapter's comes from chapters/chapters.toml.
static SNAPSHOTS: Dir = include_dir!("$CARGO_MANIFEST_DIR/../../snapshots");

impl Reference {
    /// How to render the same picture with the workbook's own binary.
    pub fn command(&self) -> String {
        let mut command = format!(
            "cargo run -p {} -- --width 160 --height 120",
            self.chapter.package()
        );
        for arg in self.verify().args.iter() {
            command.push(' ');
            command.push_str(arg);
        }
        command
    }

    /// Where the object map of this reference lives, under snapshots/.
    pub fn objects_path(&self) -> String {
        format!(
            "{}/{}.objects.txt",
            self.chapter.folder,
            self.verify().snapshot
        )
    }

    /// Where the light map of this reference lives, under snapshots/.
    pub fn lights_path(&self) -> String {
        format!(
            "{}/{}.lights.txt",
            self.chapter.folder,
            self.verify().snapshot
        )
    }

    /// The light map, if there is one and it can be read (tests/verify/lights.rs
    /// checks that every reference whose tracer lights has a current one).
    pub fn light_map(&self) -> Option<LightMap> {
        LightMap::parse(self.lights?).ok()
    }

    /// The object map, if there is one and it can be read (tests/verify/object_maps.rs
    /// checks that every reference has a current one).
    pub fn object_map(&self) -> Option<ObjectMap> {
        ObjectMap::parse(self.objects?).ok()
    }

    fn verify(&self) -> &'static VerifyReference {
        self.chapter
            .verify
            .as_ref()
            .expect("a chapter with a reference")
    }
}

/// Every chapter's reference, in the order of the chapters.
pub fn references() -> Vec<Reference> {
    chapters::all()
        .iter()
        .filter_map(|chapter| {
            let verify = chapter.verify.as_ref()?;
            let path = format!("{}/{}.snap.png", chapter.folder, verify.snapshot);
            let file = SNAPSHOTS
                .get_file(&path)
                .unwrap_or_else(|| panic!("snapshots/{path}, named in chapters.toml, is missing"));
            let text = |extension: &str| {
                let path = format!("{}/{}.{extension}", chapter.folder, verify.snapshot);
                SNAPSHOTS.get_file(&path).and_then(|f| f.contents_utf8())
            };
            Some(Reference {
                chapter,
                png: file.contents(),
                objects: text("objects.txt"),
                lights: text("lights.txt"),
            })
        })
        .collect()
}

/// The reference of a chapter named by number (`3`, `03`), folder
/// (`03-lambert`) or package (`ch03-lambert`).
pub fn reference(name: &str) -> Option<Reference> {
    let number = name.parse::<u32>().ok();
    references().into_iter().find(|r| {
        r.chapter.folder == name
            || r.chapter.package() == name
            || number == Some(r.chapter.number())
    })
}

/// The outcome of a verification.
pub struct Outcome {
    pub verdict: Verdict,
    /// Where the three-panel diff (reference | mask | yours) was written.
    pub diff: Option<PathBuf>,
    /// For a failing picture: the usual mistake that explains it, or where
    /// it differs.
    pub diagnosis: Option<Diagnosis>,
}

/// Compares the PNG at `image` with the chapter's reference and writes a
/// diff picture to `diff`.
pub fn verify(reference: &Reference, image: &Path, diff: &Path) -> Result<Outcome, String> {
    let expected = image::load_from_memory(reference.png)
        .map_err(|e| format!("the built-in reference cannot be read: {e}"))?
        .to_rgb8();
    let actual = image::open(image)
        .map_err(|e| format!("cannot read {} as an image: {e}", image.display()))?
        .to_rgb8();
    let tolerance = Tolerance::for_size(expected.width(), expected.height());
    let verdict = compare(&expected, &actual, tolerance);
    let diff = match verdict {
        Verdict::WrongSize { .. } => None,
        _ => {
            let picture = encode_png(&diff_image(&expected, &actual, tolerance));
            write_atomically(diff, &picture)
                .map_err(|e| format!("cannot write {}: {e}", diff.display()))?;
            Some(diff.to_owned())
        }
    };
    let diagnosis = if verdict.passed() {
        None
    } else {
        diagnose(
            &expected,
            &actual,
            reference.object_map().as_ref(),
            reference.light_map().as_ref(),
        )
    };
    Ok(Outcome {
        verdict,
        diff,
        diagnosis,
    })
}

/// `workbook verify`: checks your own tracer's picture against a chapter's reference.
#[derive(clap::Args, Debug, Clone)]
pub struct VerifyArgs {
    /// Check one pixel's ray tree instead of a picture:
    /// `verify --tree CHAPTER X,Y MINE.json`, MINE.json being the tree your
    /// tracer wrote for pixel X,Y of the chapter's default scene at its own
    /// size (the schema: book/appendix/ray-tree.md). It names the first
    /// ray and field that differ.
    #[arg(long)]
    pub tree: bool,

    /// The chapter: its number (3), folder (03-lambert) or package (ch03-lambert).
    pub chapter: String,

    /// Your picture of the chapter's default scene, 160×120 pixels, as PNG
    /// (each channel clamped to [0, 1] and stored as round(255·v), no
    /// gamma); with --tree, the pixel X,Y and your tree's JSON file.
    #[arg(value_name = "IMAGE.png | X,Y MINE.json", num_args = 1..=2, required = true)]
    pub files: Vec<PathBuf>,

    /// Where to write the diff picture (reference | mask | yours).
    /// Default: beside your picture, as NAME.diff.png.
    #[arg(long, conflicts_with = "tree")]
    pub diff: Option<PathBuf>,

    /// With --tree: compare with this tree (as a chapter binary writes it
    /// with --pixel X,Y --json) instead of the built-in reference, for a
    /// pixel or scene that has none.
    #[arg(long, requires = "tree", value_name = "REFERENCE.json")]
    pub against: Option<PathBuf>,
}

/// Runs `workbook verify`: exit code 0 when the picture (or tree) passes.
pub fn main(args: &VerifyArgs) -> ExitCode {
    if args.tree {
        return main_tree(args);
    }
    let [image] = args.files.as_slice() else {
        eprintln!(
            "error: verify takes the chapter and your picture (IMAGE.png); \
             to check a ray tree: verify --tree CHAPTER X,Y MINE.json"
        );
        return ExitCode::FAILURE;
    };
    let Some(reference) = reference(&args.chapter) else {
        let names: Vec<&str> = references()
            .iter()
            .map(|r| r.chapter.folder.as_str())
            .collect();
        eprintln!(
            "error: no chapter {:?}; the chapters with a reference are {}",
            args.chapter,
            names.join(", ")
        );
        return ExitCode::FAILURE;
    };
    let diff = args
        .diff
        .clone()
        .unwrap_or_else(|| image.with_extension("diff.png"));
    match verify(&reference, image, &diff) {
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
        Ok(outcome) => report(&reference, &outcome),
    }
}

/// `workbook verify --tree CHAPTER X,Y MINE.json`.
fn main_tree(args: &VerifyArgs) -> ExitCode {
    let [pixel, mine] = args.files.as_slice() else {
        eprintln!(
            "error: verify --tree takes the chapter, the pixel and your tree: verify --tree 6 160,110 mine.json"
        );
        return ExitCode::FAILURE;
    };
    let outcome = tree::parse_pixel(&pixel.to_string_lossy())
        .and_then(|pixel| tree::verify_tree(&args.chapter, pixel, mine, args.against.as_deref()));
    match outcome {
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
        Ok(outcome) => {
            println!("{outcome}");
            if outcome.passed() {
                ExitCode::SUCCESS
            } else {
                ExitCode::FAILURE
            }
        }
    }
}

/// Prints the verdict, where the diff is, and for a failing picture what to
/// render instead and what is probably wrong.
fn report(reference: &Reference, outcome: &Outcome) -> ExitCode {
    let passed = outcome.verdict.passed();
    println!(
        "{}: chapter {}: {}",
        if passed { "PASS" } else { "FAIL" },
        reference.chapter.folder,
        outcome.verdict
    );
    if let Some(diff) = &outcome.diff {
        println!("diff (reference | mask | yours): {}", diff.display());
    }
    if let Verdict::WrongSize { expected, .. } = outcome.verdict {
        println!(
            "render the chapter's default scene at {}×{}; the workbook's own picture comes from\n  {}",
            expected.0,
            expected.1,
            reference.command()
        );
    }
    if let Some(diagnosis) = &outcome.diagnosis {
        println!("{diagnosis}");
    }
    if passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
