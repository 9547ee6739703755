//! `grade-probe`: the grader runs it, never a student (see the crate's
//! documentation).
//!
//! ```text
//! grade-probe --list                              what this build probes, as JSON
//! grade-probe --seed S --exercise ID --out FILE   one exercise's values
//! grade-probe --seed S --scenes FOLDER --out FILE a chapter's seeded scenes
//!              [--png DIR]                        (and their PNGs, to look at)
//! grade-probe ... --out-fd N                      the same, written to descriptor N
//! ```
//!
//! The grader always says `--out-fd`: it passes the writing end of a pipe
//! it opened, and reads the values from the other end, so that no file
//! (which the student's code, linked into this binary, could replace with
//! a link) carries them. `--out FILE` is for a teacher trying the probe.

use std::collections::BTreeMap;
use std::process::ExitCode;

use grade_probe::{FORMAT, Probed, probes, scenes};

fn main() -> ExitCode {
    match probe(std::env::args().skip(1).collect()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("grade-probe: {e}");
            ExitCode::FAILURE
        }
    }
}

fn probe(args: Vec<String>) -> Result<(), String> {
    let value = |name: &str| {
        let at = args.iter().position(|a| a == name)?;
        args.get(at + 1).cloned()
    };
    if args.iter().any(|a| a == "--list") {
        let mut list: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
        for probe in probes::all() {
            list.entry(probe.chapter).or_default().push(probe.id);
        }
        let json = serde_json::json!({ "exercises": list, "scenes": scenes::chapters() });
        println!("{json}");
        return Ok(());
    }
    let seed = value("--seed").ok_or("--seed S is missing")?;
    let seed: u64 = seed
        .parse()
        .map_err(|_| format!("--seed {seed}: not a number"))?;
    let out = match (value("--out"), value("--out-fd")) {
        (_, Some(fd)) => Out::Descriptor(
            fd.parse()
                .map_err(|_| format!("--out-fd {fd}: not a number"))?,
        ),
        (Some(file), None) => Out::File(file),
        (None, None) => return Err("--out FILE or --out-fd N is missing".into()),
    };
    let mut probed = Probed {
        format: FORMAT.to_owned(),
        seed,
        ..Probed::default()
    };
    if let Some(id) = value("--exercise") {
        let all = probes::all();
        let probe = all.iter().find(|p| p.id == id);
        let probe = probe.ok_or_else(|| format!("no probe of exercise {id} in this build"))?;
        probed.exercises.push(probes::run(probe, seed));
    } else if let Some(chapter) = value("--scenes") {
        probed.scenes = scenes::render(&chapter, seed);
        if let Some(folder) = value("--png") {
            scenes::save_pngs(&probed.scenes, folder.as_ref())?;
        }
    } else {
        return Err("say --exercise ID or --scenes FOLDER".into());
    }
    let json = serde_json::to_vec(&probed).map_err(|e| e.to_string())?;
    out.write(&json)
}

/// Where the values go.
enum Out {
    File(String),
    Descriptor(i32),
}

impl Out {
    fn write(self, json: &[u8]) -> Result<(), String> {
        use std::io::Write;
        use std::os::fd::FromRawFd;
        match self {
            Out::File(path) => {
                std::fs::write(&path, json).map_err(|e| format!("cannot write {path}: {e}"))
            }
            Out::Descriptor(fd) => {
                // SAFETY: the grader opened `fd` for this process and
                // passes it to nothing else; it is closed when the File is
                // dropped, which ends the grader's read.
                let mut file = unsafe { std::fs::File::from_raw_fd(fd) };
                file.write_all(json)
                    .map_err(|e| format!("cannot write to descriptor {fd}: {e}"))
            }
        }
    }
}
