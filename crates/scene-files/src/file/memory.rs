//! Will the scene fit? The memory a scene needs, estimated from its object
//! count before any object is parsed (and from its meshes' triangles as
//! their OBJ files are read), and the memory the machine has.
//!
//! # Bytes per object
//!
//! What one sphere of a scene file costs, on a 64-bit machine:
//!
//! | where | bytes | alive |
//! | --- | --- | --- |
//! | its table in the file (`[[objects]]`, type, centre, radius, material) | about 106 | while loading |
//! | its records in a batch (toml's spanned values); 256 objects a batch, one batch per thread | about 3,000 | while its batch is parsed |
//! | its [`Object`](crate::Object): a `Shape` (112 bytes: the largest, a smooth triangle, has 6 vectors of 16 bytes), material index, flag | 128 | always |
//! | the same, in its batch's list, for the 32 batches parsed at once | 128 | while its group is parsed |
//! | the complete tracer's BVH: packets of 192 bytes, about 3.2 spheres each | 60 | while rendering |
//! | the complete tracer's BVH: four-wide nodes of 128 bytes, about 0.09 a sphere; or, with AVX2, eight-wide nodes of 256 bytes, about 0.11 a sphere (balls-4) | 12, or 29 | while rendering |
//! | its build: chapter 8's `Item` (box, centre, index) and binary nodes (48 bytes, about 2 per primitive), a `Primitive` (geometry, index, flag), the collapse's spans | 64 + 96 + 80 + 20 | while building |
//!
//! So loading peaks near text + 128 bytes per object, and building the BVH
//! near 128 + 260 once the text is gone. Measured peak RSS of `raybook
//! render` (whole process) on scenes from `cargo run --release -p
//! scene-files --example sphere_cloud`: 762 MiB for 2 million spheres,
//! about 400 bytes per sphere, its 106 bytes of text included (563 MiB
//! when a vector was 12 bytes, not 16; 815 MiB, about 427 bytes, with the
//! eight-wide tree, whose leaves are one packet, less full). The estimate
//! below adds a margin.

use std::sync::atomic::{AtomicU64, Ordering};

use super::outline::Outline;
use crate::SceneError;

/// The peak memory of loading and rendering one object, besides the
/// file's text (measured about 290, with a margin: see the module's table).
/// A mesh's table counts as one object before the scene is parsed; each of
/// its triangles with area counts as one more as its OBJ file is read (a
/// torus of 2 million smooth triangles, 1 million vertices and normals,
/// peaked at 689 MB rendered: about 345 bytes a triangle).
pub const BYTES_PER_OBJECT: u64 = 448;

/// What an OBJ file's vertex or normal takes while its mesh is read: a
/// vector of 16 bytes, in a list that may have twice the room it uses.
pub(crate) const BYTES_PER_VERTEX: u64 = 32;

/// Parsed whole (see [`Outline::unusual`]), toml holds spanned values of the
/// whole file at once: measured 32 bytes of memory per byte of text.
const BYTES_PER_BYTE_WHOLE: u64 = 36;

/// How much memory a scene may use.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MemoryLimit {
    pub bytes: u64,
    /// Where the number comes from, for messages (`MemAvailable in /proc/meminfo`).
    pub source: String,
}

impl MemoryLimit {
    /// What this machine can give now: `MemAvailable` from /proc/meminfo,
    /// or less if this process's cgroup has a memory limit. `None` where
    /// neither can be read (then nothing is refused).
    pub fn of_machine() -> Option<MemoryLimit> {
        let meminfo = mem_available().map(|bytes| MemoryLimit {
            bytes,
            source: "MemAvailable in /proc/meminfo".into(),
        });
        let cgroup = cgroup_room().map(|bytes| MemoryLimit {
            bytes,
            source: "the room left under this process's cgroup memory limit".into(),
        });
        match (meminfo, cgroup) {
            (Some(m), Some(c)) => Some(if c.bytes < m.bytes { c } else { m }),
            (m, c) => m.or(c),
        }
    }
}

/// What a scene's meshes may take of the memory, as their OBJ files are
/// read: the limit, less what the rest of the scene was estimated to need.
/// Meshes in different batches of objects are read in parallel and take
/// from it together.
#[derive(Debug)]
pub(crate) struct MeshBudget {
    limit: MemoryLimit,
    /// The scene's estimated need so far.
    need: AtomicU64,
}

impl MeshBudget {
    pub fn new(limit: &MemoryLimit, scene_need: u64) -> MeshBudget {
        MeshBudget {
            limit: limit.clone(),
            need: AtomicU64::new(scene_need),
        }
    }

    /// Adds `bytes` to the scene's estimated need; `Err` with the need, once
    /// it is more than the limit.
    pub fn take(&self, bytes: u64) -> Result<(), u64> {
        let need = self.need.fetch_add(bytes, Ordering::Relaxed) + bytes;
        if need > self.limit.bytes {
            return Err(need);
        }
        Ok(())
    }

    pub fn limit(&self) -> &MemoryLimit {
        &self.limit
    }
}

/// The memory a scene of `text` with this outline will need, estimated
/// before parsing its objects.
pub(super) fn estimate(text: &str, outline: &Outline) -> u64 {
    let text_bytes = text.len() as u64;
    if outline.unusual {
        text_bytes * BYTES_PER_BYTE_WHOLE
    } else {
        text_bytes + outline.objects as u64 * BYTES_PER_OBJECT
    }
}

/// Refuses a scene whose estimated need is more than `limit` allows;
/// returns the need.
pub(super) fn check(
    file: &str,
    text: &str,
    outline: &Outline,
    limit: Option<&MemoryLimit>,
) -> Result<u64, SceneError> {
    let objects = format!("{} objects", outline.objects);
    let need = estimate(text, outline);
    refuse_beyond(file, text, &objects, need, limit).map(|()| need)
}

/// Refuses an NFF scene that would need more than `limit`: its text plus
/// [`BYTES_PER_OBJECT`] a line. Every object takes a line at least (a
/// sphere one, a polygon of n corners n + 1 lines for n − 2 triangles), so
/// the lines bound the objects from above.
pub(crate) fn check_nff(
    file: &str,
    text: &str,
    limit: Option<&MemoryLimit>,
) -> Result<(), SceneError> {
    let lines = text.lines().count();
    let need = text.len() as u64 + lines as u64 * BYTES_PER_OBJECT;
    let objects = format!("up to {lines} objects (one a line)");
    refuse_beyond(file, text, &objects, need, limit)
}

/// The error for a scene of `objects` (how many, in words) in `text` that
/// would need `need` bytes, if that is more than `limit`.
fn refuse_beyond(
    file: &str,
    text: &str,
    objects: &str,
    need: u64,
    limit: Option<&MemoryLimit>,
) -> Result<(), SceneError> {
    match limit {
        Some(limit) if need > limit.bytes => Err(SceneError::at(
            file,
            text,
            None,
            "",
            format!(
                "the scene has {objects} in {} of text and would need about {} of memory \
                 to load and render (about {BYTES_PER_OBJECT} bytes per object, and the text), \
                 but only {} is available ({}); render a smaller scene, or free memory",
                size(text.len() as u64),
                size(need),
                size(limit.bytes),
                limit.source
            ),
        )),
        _ => Ok(()),
    }
}

/// Refuses a file of `bytes` whose text alone is more than `limit` allows,
/// before it is read.
pub(crate) fn check_file_size(
    file: &str,
    bytes: u64,
    limit: Option<&MemoryLimit>,
) -> Result<(), SceneError> {
    match limit {
        Some(limit) if bytes > limit.bytes => Err(SceneError::at(
            file,
            "",
            None,
            "",
            format!(
                "the file is {}, more than the {} of memory available ({}), \
                 so its scene cannot be loaded; render a smaller scene, or free memory",
                size(bytes),
                size(limit.bytes),
                limit.source
            ),
        )),
        _ => Ok(()),
    }
}

/// A number of bytes for people: `1.5 GiB`, `184.0 MiB`, `12 bytes`.
pub(crate) fn size(bytes: u64) -> String {
    const UNITS: [(&str, u64); 3] = [("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)];
    match UNITS.iter().find(|(_, unit)| bytes >= *unit) {
        Some((name, unit)) => format!("{:.1} {name}", bytes as f64 / *unit as f64),
        None => format!("{bytes} bytes"),
    }
}

/// `MemAvailable` of /proc/meminfo, in bytes.
fn mem_available() -> Option<u64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = meminfo.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// The limit of this process's memory cgroup less what it already uses,
/// for cgroup v2 (`memory.max`) or v1 (`memory.limit_in_bytes`); `None`
/// without a limit.
fn cgroup_room() -> Option<u64> {
    let cgroups = std::fs::read_to_string("/proc/self/cgroup").ok()?;
    cgroups.lines().find_map(|line| {
        let mut fields = line.splitn(3, ':');
        let (_, controllers, path) = (fields.next()?, fields.next()?, fields.next()?);
        let (dir, max, current) = match controllers {
            "" => ("/sys/fs/cgroup", "memory.max", "memory.current"),
            c if c.split(',').any(|c| c == "memory") => (
                "/sys/fs/cgroup/memory",
                "memory.limit_in_bytes",
                "memory.usage_in_bytes",
            ),
            _ => return None,
        };
        let read = |name: &str| -> Option<u64> {
            let text = std::fs::read_to_string(format!("{dir}{path}/{name}")).ok()?;
            text.trim().parse().ok() // "max" (no limit) does not parse
        };
        Some(read(max)?.saturating_sub(read(current)?))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_like_people_write_them() {
        assert_eq!(size(12), "12 bytes");
        assert_eq!(size(1536), "1.5 KiB");
        assert_eq!(size(184 << 20), "184.0 MiB");
        assert_eq!(size(3 << 30), "3.0 GiB");
    }

    #[test]
    fn the_estimate_grows_with_the_objects() {
        let text = "[[objects]]\n".repeat(1000);
        let need = estimate(&text, &Outline::of(&text));
        assert_eq!(need, text.len() as u64 + 1000 * BYTES_PER_OBJECT);
    }

    #[test]
    fn a_scene_within_the_limit_passes() {
        let text = "[[objects]]\n".repeat(10);
        let limit = MemoryLimit {
            bytes: 1 << 20,
            source: "a test".into(),
        };
        assert!(check("s.toml", &text, &Outline::of(&text), Some(&limit)).is_ok());
        assert!(check("s.toml", &text, &Outline::of(&text), None).is_ok());
    }

    #[test]
    fn meshes_take_from_one_budget_until_it_is_spent() {
        let limit = MemoryLimit {
            bytes: 1000,
            source: "a test".into(),
        };
        let budget = MeshBudget::new(&limit, 600);
        assert_eq!(budget.take(300), Ok(()));
        assert_eq!(budget.take(100), Ok(()));
        assert_eq!(budget.take(1), Err(1001));
        assert_eq!(budget.limit().bytes, 1000);
    }
}
