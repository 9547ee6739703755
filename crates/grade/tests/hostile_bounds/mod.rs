//! The hostile class's tests of the bounds on what a student's runs may
//! write: beyond their build folder inside the sandbox (`/dev`), and out of
//! it onto the teacher's disk (the probe kept for each chapter). The class
//! is `hostile.rs`'s, graded once.

use super::{row, score};

#[test]
fn a_probe_padded_past_any_honest_size_is_refused_and_never_kept() {
    let Some(padded) = row("n-padded") else {
        return;
    };
    // Kept, it would have earned its honest 3/3 and put its size on the
    // teacher's disk once per chapter graded.
    assert_eq!(score(padded), ("0", "3"), "{padded:?}");
    assert!(
        padded["why"].contains("more than the 64 MiB grading keeps"),
        "{padded:?}"
    );
}

#[test]
fn dev_and_dev_shm_take_no_more_than_their_bounds() {
    let Some(beyond) = row("o-beyond") else {
        return;
    };
    // Its `Ray::at` panics where a write beyond the bounds went through.
    assert_eq!(score(beyond), ("3", "3"), "{beyond:?}");
    assert_eq!(beyond["troubles"], "", "{beyond:?}");
}
