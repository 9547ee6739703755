//! Where a student's code runs, and what may leave it.
//!
//! Student code is untrusted. What grading does about it (the trust model):
//! * it runs in a fresh copy, never in the student's folder, which is only
//!   read (`class/submission.rs`, `class/student.rs`), and symlinks are never followed;
//! * the copy holds the reference's files but for the student's own
//!   folders (each exercise chapter's `src/`): the tests, pictures,
//!   manifest, Cargo files and lock file are the reference's, and no build
//!   script of the student's is there; edits to them are flagged, and so
//!   are sources that reach outside their chapter (`#[path]`, `include!`
//!   and its kin: `class/source_paths.rs`) and build settings among their sources;
//! * every build and test run is in bubblewrap (`sandbox/bwrap.rs`): an empty
//!   root holding the toolchain and registry sources read-only, the copy
//!   read-only, and its `target/` writable, a size-limited file system of
//!   the student's own; every namespace its own (no network, no host
//!   sockets, a PID namespace whose processes all end with the run); the
//!   student's processes together in a control group bounding their
//!   memory and number where the system allows one (`sandbox/cgroup.rs`); cargo
//!   `--offline`, with a small environment. Where the sandbox cannot
//!   start, grading refuses to, unless the teacher says
//!   `--unsafe-no-sandbox`, which every output then shows;
//! * each run is killed at its time limit, under limits on address space,
//!   file size and core dumps, with a cap on what it prints (`sandbox/limits.rs`);
//!   what stopped a run is recorded and the next one starts; Ctrl-C ends
//!   them too;
//! * the shared build artefacts are copies in the student's own target
//!   folder, never links to the base build or the teacher's (`build/share.rs`);
//! * the probe's values leave on a channel no student can redirect: the
//!   writing end of a pipe the grader opened and handed to the probe as
//!   descriptor 3 (`judging/probe.rs`), never a file. The student's code
//!   is linked into the probe and may write to the pipe too, so what
//!   comes out is data, checked against the grader's own seed, exercise
//!   and format, and worth only what its values are against the
//!   reference's. The reference's values stay in the grader's memory;
//! * the probes are built before any of the student's code runs, kept in
//!   the grader's own folder and shown to their runs read-only; they run
//!   after every chapter's tests, so nothing a probe is given (the seed,
//!   the drawn inputs) or writes reaches a run whose output a student
//!   sees, and what a student sees of the judging names a disagreement by
//!   its number only (`judging/verdict.rs`, `Verdict::for_student`);
//! * what a run may write is bounded everywhere: its build folder by
//!   `--disk`, `/tmp` and `/dev/shm` by 64 MiB, and `/dev` is read-only;
//!   what leaves it too: a probe kept over 64 MiB is refused, a chapter's
//!   failure pictures past 8 MiB, and a result keeps 1000 characters of a
//!   text and 100 flags; and whatever a student's files or output hold,
//!   grading reads them in one pass (no scan from every match again);
//! * everything the grader reads of a student's folder or build folder
//!   (the handout record, the sources, the failure pictures, what a run
//!   left) is opened beneath a folder it opened itself, with no symlink
//!   anywhere on the way, and only if it is a regular file, of a bounded
//!   size, read within a time (`sandbox/beneath.rs`); what is refused is
//!   said in the grader's words, never quoted, and flagged. Nothing
//!   outside the sandbox is created, listed, read or removed by a path
//!   that passes through a folder a student can write;
//! * what reaches the teacher's terminal and files is on one line, without
//!   control or bidirectional characters (`beneath::clean_line`), and one
//!   student's failure of any kind stops no other's grading.
//!
//! What the design still trusts, and why that is acceptable:
//! * the kernel and bubblewrap: a student who escapes a user namespace has
//!   a kernel exploit, which no grader stops; bubblewrap is small, audited
//!   and what every Flatpak application runs in, and distributions ship
//!   its fixes. A teacher who grades strangers (a MOOC) should still run
//!   `grade` in a throwaway virtual machine or account, as Gradescope does;
//! * the toolchain and the registry sources, which the students' code may
//!   read (they are public, and read-only in the sandbox), and rustc and
//!   the linker, which run on the student's source: a compiler bug that
//!   runs code at compile time runs it inside the same sandbox;
//! * the students' own copies: within its run, a student's code may write
//!   its own `target/` (its own build, its own failure pictures), so what
//!   the tests print and write is theirs to forge. Points therefore come
//!   not from a student's own report of itself but from the values its
//!   code computed on inputs it never saw, judged outside the sandbox
//!   (`judging/rule.rs`); the pictures leave only through `sandbox/outbound.rs`. An
//!   exercise that no probe covers yet is still judged by its tests, which
//!   a student can forge: every exercise of chapters 1 to 7 is probed, so
//!   none is left, but a new exercise is until its probe is written;
//! * the CPU: nothing but the time limits bounds a student's CPU time, and
//!   students graded side by side share the cores (a slow neighbour costs
//!   time, never points, since no verdict depends on speed);
//! * on cgroup v1 without a group the grader may make (an unprivileged
//!   teacher), the memory of a student's processes is bounded one process
//!   at a time (`--memory` of address space each) and their number only by
//!   the time limit; grading says so when it starts. `sandbox/cgroup.rs` says how
//!   to bound them on a cgroup-v2 system;
//! * with `--unsafe-no-sandbox`, everything: the code runs as the teacher,
//!   reads and writes what the teacher can and reaches the network. It is
//!   for a class one trusts, and every output says it was used.
//!
//! ## The attacks tried, and what each gets
//!
//! Each is a student of the hostile corpus (`tests/hostile.rs`), graded
//! in CI.
//!
//! | attack | what it gets, and why |
//! |---|---|
//! | printing `test … ok` for every test; a lookup table of the tests' values; the reference picture stored and overwritten | only its honest points: points come from the probe's values on inputs drawn at grading time; the overwrite is flagged |
//! | `#[path]`/`include!` of the reference's solution or a classmate's file | does not compile (not in its sandbox), flagged |
//! | a `setsid` child, Unix sockets outside, overwriting shared artefacts in place | dies with the run (PID namespace), hears nothing (network namespace), touches only its own copies |
//! | files over the disk, children over the memory | held by the build folder's size and the control group, noted |
//! | in the probe, `target/probe` swapped for a link to the base copy's outputs; `snapshot-failures/01-rays` for a link to a teacher's folder | nothing: the values come on the pipe, the reference's are in memory, the pictures are read beneath the build folder with no link on the way; both links flagged |
//! | a record of its own written on the pipe (with the right seed and exercise) | what its values are worth: nothing, unless they are right |
//! | `.raybook-handout.toml` a link to a secret, `/dev/stdin`, `/dev/zero`; a 1 GiB sparse file; a FIFO among its sources | graded on its honest work, each flagged; nothing quoted, waited for or read whole |
//! | a probe that panics with its arguments (the seed) | that exercise loses its points; the student sees "your code panicked", never the text |
//! | a folder named with a line break and a forged row; files and pictures named with ESC and CR | one line everywhere, the picture refused and flagged |
//! | an `.init_array` constructor that forges a record before `main`; a `#[global_allocator]` | the forged values are worth nothing; the allocator changes nothing |
//! | a `#[no_mangle] main` in place of every binary's entry point; `[patch]` in the Cargo.toml; a proc-macro crate added | the link fails (two `main`s), so nothing of it runs; the Cargo files are the reference's, the macro never built; flagged |
//! | a probe padded with 75 MiB of `include_bytes!` (kept, it was copied to the teacher's disk for every chapter, up to `--disk` each) | nothing: a probe over 64 MiB is refused unread (`build/cargo.rs`), and the exercises it judges lose their points |
//! | gigabytes written to `/dev` (bubblewrap's own tmpfs, half the memory) or `/dev/shm` | `/dev` is read-only, `/dev/shm` and `/tmp` 64 MiB (`sandbox/bwrap.rs`); the start-up trial run checks it |
//! | forty 4 MiB failure pictures a chapter (kept twice on the teacher's disk) | 8 MiB of them a chapter (`sandbox/outbound.rs`), the rest refused and flagged |
//! | a 1 MiB panic message; 2000 files added, each flagged | every text of a result cut to 1000 characters, 100 flags kept (`judging/verdict.rs`): the class's report stays small |
//! | sources of 8 MiB of `#[`, `include!(r#"` or `include!(x)` lines; tests printing 12 MiB of made-up failures | read in one pass (`class/source_paths.rs`, workbook's `progress::parse`): both were read again from every one, days and hours, and the class never finished |
//! | a hostile slice given to `--merge` (a link, a FIFO, not a slice) | refused at once, never quoted (`class/merge.rs`); a slice itself is the teacher's own output, so whoever can write one can write the gradebook |

pub mod beneath;
pub mod build_folder;
pub mod bwrap;
pub mod cgroup;
pub mod limits;
pub mod outbound;
pub mod setup;
