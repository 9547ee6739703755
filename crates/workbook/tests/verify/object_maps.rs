//! The object maps beside the references are current (and rewritten with
//! `RAYBOOK_WRITE_OBJECT_MAPS=1`).

use ch03_lambert::scene_files;
use workbook::verify::{ObjectMap, ObjectName, Reference, references, shape_name};
use workbook::workbench::snapshot::workspace_root;

/// The object map of a reference, computed from its chapter's default scene
/// as the reference is rendered (160×120, one ray per pixel through its
/// centre): each pixel's first object hit, by chapter 2's closest hit
/// through chapter 1's camera.
fn object_map(reference: &Reference) -> ObjectMap {
    let scene = scene_files::load(workspace_root().join(reference.chapter.default_scene_path()))
        .unwrap()
        .with_size(160, 120);
    assert!(
        scene.image.samples <= 1,
        "a reference has one ray per pixel"
    );
    let camera = ch02_hits::Camera::new(&scene.camera, 160, 120);
    let hit = |x, y| {
        ch02_hits::closest_hit(
            &scene.objects,
            &camera.primary_ray(x, y),
            0.0,
            f32::INFINITY,
        )
        .map(|hit| hit.object)
    };
    let objects = scene.objects.iter().map(|object| ObjectName {
        shape: shape_name(&object.shape).to_owned(),
        material: scene.material(object).name.clone(),
    });
    ObjectMap {
        width: 160,
        height: 120,
        objects: objects.collect(),
        pixels: (0..120)
            .flat_map(|y| (0..160).map(move |x| hit(x, y)))
            .collect(),
    }
}

#[test]
fn the_object_maps_are_current() {
    let write = std::env::var_os("RAYBOOK_WRITE_OBJECT_MAPS").is_some();
    let mut stale = Vec::new();
    for reference in references() {
        let name = reference.objects_path();
        let path = workspace_root().join("snapshots").join(&name);
        let picture = name
            .rsplit('/')
            .next()
            .unwrap()
            .replace(".objects.txt", ".snap.png");
        let text = object_map(&reference).to_text(&picture);
        assert_eq!(ObjectMap::parse(&text).unwrap(), object_map(&reference));
        if write {
            std::fs::write(&path, &text).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(&text) {
            stale.push(path);
        } else {
            assert_eq!(
                reference.objects,
                Some(text.as_str()),
                "the workbook binary embeds an older {name}: rebuild it (touch crates/workbook/src/verify/mod.rs)"
            );
        }
    }
    assert!(
        stale.is_empty(),
        "stale or missing object maps {stale:?}; regenerate them with\n  \
         RAYBOOK_WRITE_OBJECT_MAPS=1 cargo test -p workbook --test verify the_object_maps_are_current"
    );
}
