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
//! * what leaves the sandbox is checked: failure pictures are copied out
//!   only if they are regular files, of a bounded size, read within a
//!   time (`sandbox/outbound.rs`); anything else in their place is refused and
//!   flagged.
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

pub mod beneath;
pub mod build_folder;
pub mod bwrap;
pub mod cgroup;
pub mod limits;
pub mod outbound;
pub mod setup;
