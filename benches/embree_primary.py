"""Embree 4 (through the PyPI package embreex) tracing raybook's primary rays.

`raybook bench --primary` writes a scene's triangles and its primary rays
into a folder and runs this script on it (with $RAYBOOK_PYTHON, else
python3):

    python3 embree_primary.py FOLDER RUNS

FOLDER holds raw little-endian f32 files, written by src/bench/primary.rs:

    triangles.f32   n triangles × 3 corners × (x, y, z), in the scene's order
    origins.f32     m rays × (x, y, z)
    directions.f32  m rays × (x, y, z), of length 1, so t is a distance

The script builds Embree's scene (not timed: the commit happens in an
untimed call on one ray), then times `EmbreeScene.run` on all the rays,
RUNS times: one call, one thread (embreex loops over the rays with
rtcIntersect1, the single-ray query, in C). It prints one line per run,
`seconds S cpu C`: the wall time and the process's CPU time (no more than
the wall time if one thread did the work), and writes the hit distance of every ray of the last run to
FOLDER/t.f32 (f32, +inf where the ray hits nothing), for raybook to compare.

`python3 embree_primary.py --check` exits 0 if embreex and numpy can be
imported, and prints embreex's version.
"""

import sys
import time
from pathlib import Path


def check():
    import embreex  # noqa: F401  (imported to see that it can be)
    import numpy  # noqa: F401
    from importlib.metadata import version

    print(f"embreex {version('embreex')}")


def read(folder, name, shape):
    import numpy as np

    data = np.fromfile(folder / name, dtype="<f4")
    return np.ascontiguousarray(data.reshape(shape), dtype=np.float32)


def main(folder, runs):
    import numpy as np
    from embreex.mesh_construction import TriangleMesh
    from embreex.rtcore_scene import EmbreeScene

    triangles = read(folder, "triangles.f32", (-1, 3, 3))
    origins = read(folder, "origins.f32", (-1, 3))
    directions = read(folder, "directions.f32", (-1, 3))
    scene = EmbreeScene()
    TriangleMesh(scene, triangles)
    # The first query commits the scene: Embree builds its BVH there.
    scene.run(origins[:1], directions[:1])
    for _ in range(runs):
        start, cpu = time.perf_counter(), time.process_time()
        hits = scene.run(origins, directions, output=1)
        seconds = time.perf_counter() - start
        cpu = time.process_time() - cpu
        print(f"seconds {seconds:.9f} cpu {cpu:.9f}", flush=True)
    t = np.where(hits["primID"] >= 0, hits["tfar"], np.inf).astype("<f4")
    t.tofile(folder / "t.f32")


if __name__ == "__main__":
    if sys.argv[1:] == ["--check"]:
        check()
    else:
        main(Path(sys.argv[1]), int(sys.argv[2]))
