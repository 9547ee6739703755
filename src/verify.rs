//! `raybook verify CHAPTER IMAGE.png`: checks a picture made by a student's
//! own tracer, in any language, against the chapter's reference picture.
//!
//! The reference is the chapter's default scene rendered at 160×120 (the
//! snapshot size); the comparison is the snapshot tolerance of every test.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::toolkit::compare::{Tolerance, Verdict, compare, diff_image};
use crate::toolkit::image::{encode_png, write_atomically};

/// A chapter's reference picture for its default scene.
pub struct Reference {
    /// The chapter's folder under chapters/.
    pub chapter: &'static str,
    /// How to render the same picture with the workbook's own binary.
    pub command: &'static str,
    pub png: &'static [u8],
}

/// The references, built into the binary so that it works from anywhere.
pub const REFERENCES: &[Reference] = &[
    Reference {
        chapter: "01-rays",
        command: "cargo run -p ch01-rays -- --width 160 --height 120",
        png: include_bytes!("../snapshots/01-rays/default.snap.png"),
    },
    Reference {
        chapter: "02-hits",
        command: "cargo run -p ch02-hits -- --width 160 --height 120 --view flat",
        png: include_bytes!("../snapshots/02-hits/flat.snap.png"),
    },
    Reference {
        chapter: "03-lambert",
        command: "cargo run -p ch03-lambert -- --width 160 --height 120",
        png: include_bytes!("../snapshots/03-lambert/default.snap.png"),
    },
    Reference {
        chapter: "04-shadows",
        command: "cargo run -p ch04-shadows -- --width 160 --height 120",
        png: include_bytes!("../snapshots/04-shadows/default.snap.png"),
    },
    Reference {
        chapter: "05-reflection",
        command: "cargo run -p ch05-reflection -- --width 160 --height 120",
        png: include_bytes!("../snapshots/05-reflection/default.snap.png"),
    },
    Reference {
        chapter: "06-refraction",
        command: "cargo run -p ch06-refraction -- --width 160 --height 120",
        png: include_bytes!("../snapshots/06-refraction/default.snap.png"),
    },
    Reference {
        chapter: "07-termination",
        command: "cargo run -p ch07-termination -- --width 160 --height 120",
        png: include_bytes!("../snapshots/07-termination/default.snap.png"),
    },
];

/// The reference of a chapter named by number (`3`, `03`), folder
/// (`03-lambert`) or package (`ch03-lambert`).
pub fn reference(name: &str) -> Option<&'static Reference> {
    let name = name.trim_start_matches("ch");
    REFERENCES.iter().find(|r| {
        let number = &r.chapter[..2];
        name == r.chapter || name == number || name.parse::<u32>().ok() == number.parse().ok()
    })
}

/// The outcome of a verification.
pub struct Outcome {
    pub verdict: Verdict,
    /// Where the three-panel diff (reference | mask | yours) was written.
    pub diff: Option<PathBuf>,
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
    Ok(Outcome { verdict, diff })
}

/// `raybook verify`: checks your own tracer's picture against a chapter's reference.
#[derive(clap::Args, Debug, Clone)]
pub struct VerifyArgs {
    /// The chapter: its number (3), folder (03-lambert) or package (ch03-lambert).
    pub chapter: String,

    /// Your picture of the chapter's default scene, 160×120 pixels, as PNG
    /// (each channel clamped to [0, 1] and stored as round(255·v), no gamma).
    pub image: PathBuf,

    /// Where to write the diff picture (reference | mask | yours).
    /// Default: beside your picture, as NAME.diff.png.
    #[arg(long)]
    pub diff: Option<PathBuf>,
}

/// Runs `raybook verify`: exit code 0 when the picture passes.
pub fn main(args: &VerifyArgs) -> ExitCode {
    let Some(reference) = reference(&args.chapter) else {
        let names: Vec<&str> = REFERENCES.iter().map(|r| r.chapter).collect();
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
        .unwrap_or_else(|| args.image.with_extension("diff.png"));
    match verify(reference, &args.image, &diff) {
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
        Ok(outcome) => report(reference, &outcome),
    }
}

fn report(reference: &Reference, outcome: &Outcome) -> ExitCode {
    let passed = outcome.verdict.passed();
    println!(
        "{}: chapter {}: {}",
        if passed { "PASS" } else { "FAIL" },
        reference.chapter,
        outcome.verdict
    );
    if let Some(diff) = &outcome.diff {
        println!("diff (reference | mask | yours): {}", diff.display());
    }
    if let Verdict::WrongSize { expected, .. } = outcome.verdict {
        println!(
            "render the chapter's default scene at {}×{}; the workbook's own picture comes from\n  {}",
            expected.0, expected.1, reference.command
        );
    }
    if passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
