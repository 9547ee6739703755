//! The merge's checks, on slices written here (no grading).

use super::*;
use crate::class::shard::{GradedWith, write};
use crate::judging::exercise_tests::Tests;
use crate::judging::verdict::{ChapterRun, Picture};

const CLASS: [&str; 6] = ["ada", "alan", "barbara", "edsger", "grace", "niklaus"];

/// What every slice of the test's class was graded with.
fn graded_with() -> GradedWith {
    GradedWith {
        format: "f".to_owned(),
        reference: "0.1.0 @ abc".to_owned(),
        reference_hash: "h".to_owned(),
        settings: "Settings { chapters: [01-rays], seed: 7 }".to_owned(),
        seed: 7,
        tests: Tests::default(),
        class: CLASS.map(String::from).to_vec(),
    }
}

/// Slice `k` of `n` of the class, as grade --shard writes it, into `dir`.
fn slice(dir: &Path, k: usize, n: usize, change: impl Fn(&mut ShardFile)) {
    let shard = Shard { k, n };
    let names = CLASS.map(String::from);
    let slugs = slugs(&names);
    let students = (names.iter().zip(&slugs))
        .filter(|(name, _)| shard.holds(name))
        .map(|(name, slug)| StudentResult {
            name: name.clone(),
            slug: slug.clone(),
            seconds: k as f64,
            ..StudentResult::default()
        })
        .collect();
    let mut file = ShardFile {
        shard,
        graded_with: graded_with(),
        students,
    };
    change(&mut file);
    write(dir, &file).unwrap();
}

/// The slices in `dirs`, read and checked: the students joined, or why not.
fn merged(dirs: &[&Path]) -> Result<Vec<String>, String> {
    let dirs: Vec<PathBuf> = dirs.iter().map(|d| d.to_path_buf()).collect();
    let slices = read_slices(&dirs)?;
    complete(&slices)?;
    same(&slices)?;
    let joined = join(&slices)?;
    Ok(joined.into_iter().map(|r| r.name).collect())
}

#[test]
fn slices_in_one_folder_or_many_join_in_the_class_order() {
    let one = tempfile::tempdir().unwrap();
    for k in 1..=3 {
        slice(one.path(), k, 3, |_| {});
    }
    assert_eq!(merged(&[one.path()]).unwrap(), CLASS);
    let many: Vec<_> = (0..4).map(|_| tempfile::tempdir().unwrap()).collect();
    for (k, dir) in (1..=4).zip(&many) {
        slice(dir.path(), k, 4, |_| {});
    }
    let dirs: Vec<&Path> = many.iter().rev().map(|d| d.path()).collect();
    assert_eq!(merged(&dirs).unwrap(), CLASS);
}

#[test]
fn a_missing_a_repeated_or_a_foreign_slice_is_refused() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    slice(a.path(), 1, 3, |_| {});
    slice(a.path(), 3, 3, |_| {});
    let error = merged(&[a.path()]).unwrap_err();
    assert!(error.contains("slices missing: 2/3"), "{error}");
    slice(b.path(), 2, 3, |_| {});
    slice(b.path(), 3, 3, |_| {});
    let error = merged(&[a.path(), b.path()]).unwrap_err();
    assert!(error.contains("slice 3/3 is given twice"), "{error}");
    std::fs::remove_file(b.path().join("shard-3-of-3.json")).unwrap();
    assert_eq!(merged(&[a.path(), b.path()]).unwrap(), CLASS);
    slice(b.path(), 1, 2, |_| {});
    let error = merged(&[a.path(), b.path()]).unwrap_err();
    assert!(error.contains("slices of different runs"), "{error}");
    let empty = tempfile::tempdir().unwrap();
    let error = merged(&[empty.path()]).unwrap_err();
    assert!(error.contains("no slice here"), "{error}");
}

/// A change to a slice's file.
type Change = fn(&mut ShardFile);

#[test]
fn slices_graded_with_other_settings_references_or_classes_are_refused() {
    let changes: [(&str, Change); 4] = [
        ("different settings", |f| {
            f.graded_with.settings = f.graded_with.settings.replace("seed: 7", "seed: 8")
        }),
        ("different reference_hash", |f| {
            f.graded_with.reference_hash = "other".to_owned()
        }),
        ("different class", |f| {
            f.graded_with.class.push("zuse".to_owned())
        }),
        ("different tests", |f| {
            f.graded_with
                .tests
                .chapters
                .insert("01-rays".to_owned(), vec![]);
        }),
    ];
    for (said, change) in changes {
        let dir = tempfile::tempdir().unwrap();
        slice(dir.path(), 1, 2, |_| {});
        slice(dir.path(), 2, 2, change);
        let error = merged(&[dir.path()]).unwrap_err();
        assert!(error.contains(said), "{said}: {error}");
    }
    let dir = tempfile::tempdir().unwrap();
    slice(dir.path(), 1, 2, |_| {});
    slice(dir.path(), 2, 2, |f| {
        f.graded_with.settings = f.graded_with.settings.replace("seed: 7", "seed: 8")
    });
    let error = merged(&[dir.path()]).unwrap_err();
    assert!(error.contains("seed: 7 }\" against …"), "{error}");
}

#[test]
fn a_slice_must_hold_its_own_students_and_only_them() {
    let dir = tempfile::tempdir().unwrap();
    slice(dir.path(), 1, 2, |_| {});
    slice(dir.path(), 2, 2, |f| {
        assert!(
            !f.students.is_empty(),
            "slice 2 of the test's class is empty"
        );
        f.students.pop();
    });
    let error = merged(&[dir.path()]).unwrap_err();
    assert!(error.contains("no result for"), "{error}");
    // A student of the other slice, or one given twice: too many results.
    slice(dir.path(), 2, 2, |f| {
        let mut extra = f.students[0].clone();
        extra.name = "ada".to_owned();
        extra.slug = "ada".to_owned();
        f.students.push(extra);
    });
    let error = merged(&[dir.path()]).unwrap_err();
    assert!(error.contains("does not grade"), "{error}");
}

#[test]
fn only_pictures_that_are_files_of_the_students_folder_are_copied() {
    let (from, out) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let picture = |diff: &str| ChapterRun {
        pictures: vec![Picture {
            name: "default".to_owned(),
            diff: Some(diff.to_owned()),
        }],
        ..ChapterRun::default()
    };
    let k = 1;
    slice(from.path(), k, 1, |f| {
        f.students[0].chapters = vec![picture("ada/01-rays/default.diff.png")]
    });
    let png = from.path().join("report/ada/01-rays/default.diff.png");
    std::fs::create_dir_all(png.parent().unwrap()).unwrap();
    std::fs::write(&png, b"png").unwrap();
    let copied = |from: &Path| {
        let slices = read_slices(&[from.to_owned()]).unwrap();
        copy_pictures(&slices, out.path())
    };
    copied(from.path()).unwrap();
    let to = out.path().join("report/ada/01-rays/default.diff.png");
    assert_eq!(std::fs::read(to).unwrap(), b"png");
    for diff in ["alan/01-rays/default.diff.png", "ada/../../etc/passwd"] {
        slice(from.path(), k, 1, |f| {
            f.students[0].chapters = vec![picture(diff)]
        });
        let error = copied(from.path()).unwrap_err();
        assert!(
            error.contains("is not a file of their folder in"),
            "{error}"
        );
    }
    std::fs::remove_file(&png).unwrap();
    std::os::unix::fs::symlink("/etc/hostname", &png).unwrap();
    slice(from.path(), k, 1, |f| {
        f.students[0].chapters = vec![picture("ada/01-rays/default.diff.png")]
    });
    assert!(copied(from.path()).is_err(), "a symlink is refused");
}

/// Makes a file of some kind at a path.
type MakeFile = fn(&Path);

/// A slice that is a link (to a terminal, to a device that never ends) or
/// a FIFO is refused at once and never quoted; one whose names hold line
/// breaks and escapes merges, and the outputs show them on one line.
#[test]
fn a_hostile_slice_is_refused_without_waiting_or_quoting() {
    let makers: [(&str, MakeFile); 3] = [
        ("stdin", |p: &Path| {
            std::os::unix::fs::symlink("/dev/stdin", p).unwrap()
        }),
        ("zero", |p: &Path| {
            std::os::unix::fs::symlink("/dev/zero", p).unwrap()
        }),
        ("fifo", |p: &Path| {
            let name = std::ffi::CString::new(p.as_os_str().as_encoded_bytes()).unwrap();
            // SAFETY: a valid C string.
            assert_eq!(unsafe { libc::mkfifo(name.as_ptr(), 0o644) }, 0);
        }),
    ];
    for (name, make) in makers {
        let dir = tempfile::tempdir().unwrap();
        slice(dir.path(), 1, 2, |_| {});
        make(&dir.path().join("shard-2-of-2.json"));
        let start = std::time::Instant::now();
        let error = merged(&[dir.path()]).unwrap_err();
        assert!(start.elapsed().as_secs() < 5, "{name}: it waited");
        assert!(
            error.contains("refused") || error.contains("never followed"),
            "{name}: {error}"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("shard-1-of-1.json"), "root:x:0:0:secret").unwrap();
    let error = merged(&[dir.path()]).unwrap_err();
    assert!(
        error.contains("not a slice") && !error.contains("secret"),
        "{error}"
    );
}
