//! `cargo run -q -p lab`: the student's lab bench in the browser.

use std::process::ExitCode;
use std::time::Duration;

use lab::launch::{RedirectFile, open_with, openers};

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

/// How long the redirecting page is kept: the browser reads it once, when
/// it starts (the lab ends by Ctrl-C, with no chance to clean up).
const KEEP_THE_PAGE: Duration = Duration::from_secs(60);

/// Opens `url` in the browser through a page only the user can read (see
/// [`lab::launch`]: never the address itself on a command line), if there
/// is an opener; the page is removed after [`KEEP_THE_PAGE`].
fn open(url: &str) -> bool {
    let page = match RedirectFile::new(url) {
        Ok(page) => page,
        Err(e) => {
            eprintln!("cannot write the page that opens the lab: {e}");
            return false;
        }
    };
    let opened = (openers().iter()).any(|program| open_with(program, page.path()).is_ok());
    if opened {
        std::thread::spawn(move || {
            std::thread::sleep(KEEP_THE_PAGE);
            drop(page);
        });
    }
    opened
}
