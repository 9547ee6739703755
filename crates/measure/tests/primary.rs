//! `raybook bench --primary`: the rays it times are the renderer's primary
//! rays, it reports a row per scene, and it goes on without Embree.
//! (No timing is asserted: speed is shown by the bench, not by tests.
//! Where Embree's numbers are checked, a fake Python stands in for it and
//! reports times fixed in advance.)

use std::process::{Command, Output};

use measure::bench::{PYTHON_VAR, hit_distances, primary_rays, primary_world};
use raybook::toolkit::Scene;
use raybook::workbench::snapshot::workspace_root;

fn spd(name: &str, width: u32, height: u32) -> Scene {
    let path = workspace_root().join("scenes/spd").join(name);
    raybook::nff::load(path).unwrap().with_size(width, height)
}

/// For each pixel, row by row: does the renderer's picture show something
/// other than the background there?
fn rendered_hits(scene: &Scene) -> Vec<bool> {
    let (image, _) = raybook::render(scene, || {});
    let background = scene.image.background;
    (0..scene.image.height)
        .flat_map(|y| (0..scene.image.width).map(move |x| (x, y)))
        .map(|(x, y)| image.get(x, y) != background)
        .collect()
}

#[test]
fn the_primary_rays_hit_where_the_renderer_shows_the_scene() {
    // Not square, so that rows and columns cannot be swapped unnoticed.
    for name in ["tetra-3.nff", "teapot-2.nff"] {
        let scene = spd(name, 24, 16);
        let rays = primary_rays(&scene);
        assert_eq!(rays.len(), 24 * 16, "{name}: one ray per pixel");
        let hits: Vec<bool> = hit_distances(&primary_world(&scene), &rays)
            .iter()
            .map(|t| t.is_finite())
            .collect();
        let shown = rendered_hits(&scene);
        assert!(
            shown.iter().any(|&s| s) && shown.iter().any(|&s| !s),
            "{name}: the test needs pixels of both kinds"
        );
        let differ: Vec<usize> = (0..hits.len()).filter(|&i| hits[i] != shown[i]).collect();
        assert!(differ.is_empty(), "{name}: pixels {differ:?} differ");
    }
}

fn bench(args: &[&str], python: Option<&str>) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raybook"));
    command.args(["bench", "--primary", "--quiet"]).args(args);
    if let Some(python) = python {
        command.env(PYTHON_VAR, python);
    }
    command.output().unwrap()
}

use test_support::table_row::row;

#[test]
fn a_tiny_scene_gets_a_row_with_its_rays_hits_and_throughput() {
    let out = bench(
        &[
            "--only",
            "tetra-3",
            "--size",
            "16",
            "--runs",
            "1",
            "--no-embree",
        ],
        None,
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cells = row(&stdout, "tetra-3");
    assert_eq!(cells.len(), 14, "{cells:?}");
    assert_eq!(cells[1], "64", "primitives");
    assert_eq!(cells[2], "256", "16×16 rays");
    let shown = rendered_hits(&spd("tetra-3.nff", 16, 16));
    let shown = shown.iter().filter(|&&s| s).count();
    assert_eq!(
        cells[3],
        shown.to_string(),
        "hits: the pixels that show the scene"
    );
    for (column, cell) in [(4, &cells[4]), (5, &cells[5]), (6, &cells[6])] {
        let mrays: f64 = cell.parse().unwrap();
        assert!(mrays > 0.0, "column {column}: {cell} Mrays/s");
    }
    for (column, cell) in cells.iter().enumerate().skip(7).take(2) {
        assert_eq!(cell, "not run (--no-embree)", "column {column}");
    }
    for (column, cell) in cells.iter().enumerate().skip(9) {
        assert_eq!(cell, "–", "column {column}");
    }
    assert_eq!(
        stdout.lines().filter(|l| l.starts_with("| ")).count(),
        2,
        "header and one row"
    );
}

#[test]
fn without_embree_the_table_says_how_to_install_it() {
    let out = bench(
        &["--only", "tetra-3", "--size", "8", "--runs", "1"],
        Some("/nonexistent/python3"),
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    let cells = row(&stdout, "tetra-3");
    let why = "not installed: pip install embreex numpy";
    assert_eq!(cells[7], why, "one thread");
    assert_eq!(cells[8], why, "per thread, on as many threads as raybook");
    assert_eq!(cells[11], "–", "no ratio of the same threads");
}

/// Only where embreex is installed ($RAYBOOK_PYTHON, else python3) does
/// this compare; elsewhere the table must say it is not.
#[test]
fn where_embree_runs_it_agrees_with_raybook_and_spheres_are_left_out() {
    let out = bench(
        &[
            "--only", "tetra-3", "--only", "balls-1", "--size", "32", "--runs", "1",
        ],
        None,
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    let tetra = row(&stdout, "tetra-3");
    if tetra[7].starts_with("not installed") {
        assert_eq!(row(&stdout, "balls-1")[7], tetra[7]);
        return;
    }
    // "99.999 % (3 differ)"
    let percent = |cell: &str| -> f64 { cell.split(" %").next().unwrap().parse().unwrap() };
    for column in [7, 8, 9, 10, 11] {
        assert!(tetra[column].parse::<f64>().unwrap() > 0.0, "{tetra:?}");
    }
    assert!(percent(&tetra[12]) >= 99.9, "hit/miss: {tetra:?}");
    assert!(percent(&tetra[13]) >= 99.9, "distances: {tetra:?}");
    let balls = row(&stdout, "balls-1");
    assert_eq!(balls[7], "n/a (embreex has triangles only)");
    assert_eq!(balls[8], balls[7]);
}

/// Embree's columns, from a fake Python whose report is known (a shell
/// script: Unix only).
#[cfg(unix)]
mod fake_embree {
    use super::{bench, row};

    /// A stand-in for a Python with embreex, as a shell script: it answers
    /// `--check`, reports three one-thread runs (median 0.0002 s) and, when
    /// asked for 2 processes, three runs of 2 (median 0.0004 s; the slower
    /// process's time 1, 4/3 and 2 times the faster's), in the lines
    /// `crates/measure/src/bench/embree_primary.py` prints, and writes a distance (0) per ray.
    const FAKE_PYTHON: &str = r#"#!/bin/sh
    # $1 is the script, $2 the folder (or --check), $3 the runs, $4 the processes.
    if [ "$2" = "--check" ]; then echo "embreex fake"; exit 0; fi
    bytes=$(wc -c < "$2/origins.f32")
    head -c $((bytes / 3)) /dev/zero > "$2/t.f32"
    echo "seconds 0.0009 cpu 0.0009"
    echo "seconds 0.0002 cpu 0.0002"
    echo "seconds 0.0001 cpu 0.0001"
    if [ "$4" = 2 ]; then
      echo "parallel 2 seconds 0.0001 cpu 0.0002 busy 0.0001 0.0001"
      echo "parallel 2 seconds 0.0004 cpu 0.0008 busy 0.0004 0.0003"
      echo "parallel 2 seconds 0.0010 cpu 0.0015 busy 0.0010 0.0005"
    fi
    "#;

    /// The fake Python, written into a folder of its own; its path.
    fn fake_python(name: &str) -> std::path::PathBuf {
        use std::os::unix::fs::PermissionsExt;
        let folder = std::env::temp_dir().join(format!("raybook-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("python");
        std::fs::write(&path, FAKE_PYTHON).unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
        path
    }

    /// The table's number in `cell`.
    fn number(cell: &str) -> f64 {
        cell.parse()
            .unwrap_or_else(|_| panic!("{cell:?} is not a number"))
    }

    /// The bench's report on tetra-3 at 16×16 (256 rays), with the fake
    /// Embree.
    fn fake_report(threads: &str) -> String {
        let python = fake_python(&format!("primary-fake-python-{threads}"));
        let out = bench(
            &[
                "--only",
                "tetra-3",
                "--size",
                "16",
                "--runs",
                "3",
                "--threads",
                threads,
            ],
            Some(python.to_str().unwrap()),
        );
        let _ = std::fs::remove_dir_all(python.parent().unwrap());
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{stdout}\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        stdout.into_owned()
    }

    #[test]
    fn embrees_threads_are_the_median_of_its_parallel_lines_per_process() {
        let report = fake_report("2");
        let cells = row(&report, "tetra-3");
        // 256 rays: in 0.0002 s, 1.28 Mrays/s; in 0.0004 s on 2, 0.32 each.
        assert_eq!(cells[7], "1.28", "Embree, 1 thread: {cells:?}");
        assert_eq!(cells[8], "0.32", "Embree per thread, 2 threads: {cells:?}");
        let per_thread = number(&cells[6]);
        // Each ratio within what rounding the cells to 0.01 allows.
        let near =
            |cell: &str, expected: f64| (number(cell) - expected).abs() < 0.01 + 0.005 / 0.32;
        assert!(near(&cells[10], per_thread / 1.28), "{cells:?}");
        assert!(near(&cells[11], per_thread / 0.32), "{cells:?}");
        assert!(
            report.contains("note: tetra-3: Embree's slowest process took 1.33 times"),
            "the median unevenness of the shares: {report}"
        );
    }

    #[test]
    fn on_one_thread_embrees_threads_are_its_one_thread() {
        // The fake prints no `parallel` lines unless asked for 2 processes.
        let report = fake_report("1");
        let cells = row(&report, "tetra-3");
        assert_eq!(cells[8], cells[7], "{cells:?}");
        assert_eq!(cells[11], cells[10], "{cells:?}");
        assert!(!report.contains("slowest process"), "{report}");
    }
}
