//! `cargo run -q -p lab`: the student's lab bench in the browser.

use std::process::{Command, ExitCode, Stdio};

use clap::Parser;

/// Serves your lab bench on this machine and opens it in the browser: the
/// chapters and their progress, your picture beside the reference, any
/// pixel's ray tree beside the reference's. It follows your saves under
/// chapters/. Ctrl-C stops it.
#[derive(Parser)]
#[command(version)]
struct Args {
    /// Only print the page's address; do not open a browser.
    #[arg(long)]
    no_open: bool,

    /// The port on 127.0.0.1 (0: any free one).
    #[arg(long, default_value_t = 0)]
    port: u16,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let lab = workbook::workspace::current_workspace()
        .and_then(|root| lab::Lab::start(root, args.port, true));
    let lab = match lab {
        Ok(lab) => lab,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let url = lab.url();
    println!("the lab is at {url}");
    println!("(only this machine can open it; Ctrl-C stops it)");
    if !args.no_open && !open(&url) {
        println!("open that address in your browser");
    }
    lab.serve();
    ExitCode::SUCCESS
}

/// Opens `url` with xdg-open (macOS: open), if there is one. (Not `open`
/// elsewhere: on Debian that is openvt.)
fn open(url: &str) -> bool {
    let programs: &[&str] = if cfg!(target_os = "macos") {
        &["open"]
    } else {
        &["xdg-open"]
    };
    programs.iter().any(|program| {
        Command::new(program)
            .arg(url)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .is_ok()
    })
}
