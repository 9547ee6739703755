//! The ray tree names the object that blocks a shadow ray.

use ch04_shadows::ShadowStart;
use ch04_shadows::ray_tree::explain;
use ch04_shadows::scene_files;
use ch04_shadows::workbench::cli::Pixel;
use ch04_shadows::workbench::ray_tree::{LightStatus, RayTree};

/// The eye looks straight down at the origin, on a floor; a ball sits
/// halfway between the origin and the light at (3, 4, 0), off the eye's ray.
const BALL_IN_THE_WAY: &str = r#"
[camera]
eye = [0.0, 5.0, 0.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
vfov = 20.0

[image]
width = 3
height = 3

[materials.white]
color = [0.8, 0.8, 0.8]

[[lights]]
type = "point"
position = [3.0, 4.0, 0.0]
intensity = 10.0

[[objects]]
type = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0
material = "white"

[[objects]]
type = "sphere"
center = [1.5, 2.0, 0.0]
radius = 0.5
material = "white"
"#;

#[test]
fn a_blocked_light_names_its_blocker() {
    let scene = scene_files::parse(BALL_IN_THE_WAY, "ball.toml").unwrap();
    let (tracer, primary) = explain(&scene, Pixel { x: 1, y: 1 }, ShadowStart::Offset);
    let hit = primary.hit.as_ref().unwrap();
    assert_eq!((hit.object, hit.shape.as_str()), (0, "plane"));
    let light = &primary.lights[0];
    assert_eq!(light.status, LightStatus::Blocked);
    assert_eq!(light.adds, [0.0; 3]);
    let shadow = light.shadow_ray.as_ref().unwrap();
    let blocker = shadow.blocked_by.as_ref().unwrap();
    assert_eq!((blocker.object, blocker.shape.as_str()), (1, "sphere"));
    // The ball's near side is 2.5 − 0.5 along the shadow ray, the light at 5.
    assert!((shadow.blocker_t.unwrap() - 2.0).abs() < 1e-3, "{shadow:?}");
    assert!((shadow.t_max - 5.0).abs() < 1e-3, "{shadow:?}");
    assert_eq!(primary.color, Some([0.0; 3]));
    let tree = RayTree {
        chapter: "04-shadows".into(),
        scene: "ball.toml".into(),
        pixel: [1, 1],
        image: [3, 3],
        samples: 1,
        tracer,
        primary,
    };
    let text = tree.to_text();
    assert!(
        text.contains(": blocked by object 1 (sphere) at t = 2"),
        "{text}"
    );
}
