//! Writes a scene of many small spheres, to measure how loading and
//! rendering grow with the objects:
//!
//! ```text
//! cargo run --release -p ch00-toolkit --example sphere_cloud -- 2000000 big.toml
//! /usr/bin/time -v target/release/raybook render big.toml --output /tmp/big.png
//! ```

use std::io::BufWriter;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(count), Some(path)) = (args.first().and_then(|n| n.parse().ok()), args.get(1)) else {
        eprintln!("usage: sphere_cloud COUNT FILE.toml");
        return ExitCode::FAILURE;
    };
    let written = std::fs::File::create(path)
        .and_then(|file| scene_files::write_sphere_cloud(BufWriter::new(file), count));
    match written {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cannot write {path}: {e}");
            ExitCode::FAILURE
        }
    }
}
