//! `grade`'s command line: the class, the reference, the outputs, the
//! limits, the slices and the cache.

use std::path::PathBuf;

use crate::class::shard;

/// `grade`: grades a class of handouts against the reference.
#[derive(clap::Args, Debug, Clone)]
pub struct GradeArgs {
    /// The class: a folder with one subfolder per student, each a handout
    /// (a plain folder or a git checkout).
    #[arg(required_unless_present_any = ["one", "merge"], conflicts_with_all = ["one", "merge"])]
    pub students: Option<PathBuf>,

    /// Grade one submission (a handout folder) instead of a class, as
    /// Gradescope's autograder runs it.
    #[arg(long, value_name = "DIR")]
    pub one: Option<PathBuf>,

    /// With --one: write Gradescope's results.json here.
    #[arg(long, value_name = "FILE", requires = "one")]
    pub gradescope: Option<PathBuf>,

    /// The reference workspace (default: the one this runs in).
    #[arg(long, value_name = "DIR")]
    pub reference: Option<PathBuf>,

    /// Where to write the outputs and keep the cache (default:
    /// target/grade in the reference).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,

    /// The chapters to grade: `1-3`, `1,2,5` (default: every chapter with
    /// exercises).
    #[arg(long, value_name = "LIST")]
    pub chapters: Option<String>,

    /// Seconds a chapter's tests may run before they are killed.
    #[arg(long, default_value_t = 60, value_name = "SECONDS")]
    pub timeout: u64,

    /// Seconds a chapter's build may take before it is killed.
    #[arg(long, default_value_t = 900, value_name = "SECONDS")]
    pub build_timeout: u64,

    /// Memory of a student's processes together (a control group, where
    /// the system lets grading make one), and address space of each, in
    /// MiB.
    #[arg(long, default_value_t = 4096, value_name = "MIB")]
    pub memory: u64,

    /// Room for a student's build output (their copy's target folder, a
    /// size-limited file system of its own), in MiB.
    #[arg(long, default_value_t = 4096, value_name = "MIB")]
    pub disk: u64,

    /// Run the students' code WITHOUT the sandbox, as the teacher (only for
    /// a class you trust, on a system without bubblewrap or user
    /// namespaces). Every output says so.
    #[arg(long)]
    pub unsafe_no_sandbox: bool,

    /// What a build or test run may print, in MiB, before it is killed.
    #[arg(long, default_value_t = 16, value_name = "MIB")]
    pub output: u64,

    /// Students graded side by side (default: the number of cores).
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,

    /// The points per exercise, a TOML file (default: points.toml in the
    /// output folder, written with one point each on the first run).
    #[arg(long, value_name = "FILE")]
    pub points: Option<PathBuf>,

    /// Grade every student again, even those whose files have not changed
    /// since the last run.
    #[arg(long)]
    pub again: bool,

    /// The seed of the exercises' inputs and scenes (default: the one in
    /// seed.txt in the output folder from an earlier run, else drawn anew;
    /// either way kept there, never handed out). Give the same one to
    /// reproduce a report; every slice of a class (--shard) needs the same.
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,

    /// Grade the K-th of N slices of the class (1 ≤ K ≤ N), on one of N
    /// machines: a student's slice is a hash of their folder's name, so it
    /// stays the same when students are added. Writes
    /// `shard-K-of-N.json` (and the slice's pictures) into the output
    /// folder, for `--merge`; the points are applied there.
    #[arg(long, value_name = "K/N", conflicts_with = "one")]
    pub shard: Option<shard::Shard>,

    /// Join the slices in these folders (each holds `shard-K-of-N.json`
    /// files, from `--shard`) into the outputs of one run over the whole
    /// class. Refuses slices that were graded against other references,
    /// settings or chapters, or of another class, and a slice that is
    /// missing or given twice.
    #[arg(long, value_name = "DIR", num_args = 1.., conflicts_with_all = ["one", "shard"])]
    pub merge: Vec<PathBuf>,

    /// Where to keep the cache: the reference's build, the students'
    /// copies and their results (default: .cache in the output folder).
    /// On a cluster, a node's own disk builds faster than a shared one.
    /// One grading at a time in a cache folder.
    #[arg(long, value_name = "DIR")]
    pub cache: Option<PathBuf>,
}
