//! `cargo run -p diagrams`: writes every chapter's diagrams anew, into
//! `chapters/<chapter>/diagrams/<name>.svg`, and says which ones changed.

use std::process::ExitCode;

fn main() -> ExitCode {
    let root = diagrams::workspace_root();
    let mut changed = 0;
    for diagram in diagrams::all() {
        let path = root.join(diagram.path());
        let before = std::fs::read_to_string(&path).ok();
        if before.as_deref() == Some(diagram.svg.as_str()) {
            continue;
        }
        let written = path
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(&path, &diagram.svg));
        if let Err(e) = written {
            eprintln!("error: cannot write {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        println!("wrote {}", diagram.path().display());
        changed += 1;
    }
    println!("{changed} diagrams written, the others unchanged");
    ExitCode::SUCCESS
}
