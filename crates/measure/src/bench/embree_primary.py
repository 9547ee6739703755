"""Embree 4 (through the PyPI package embreex) tracing raybook's primary rays.

`raybook bench --primary` writes a scene's triangles and its primary rays
into a folder and runs this script on it (with $RAYBOOK_PYTHON, else
python3):

    python3 embree_primary.py FOLDER RUNS [PROCESSES]

FOLDER holds raw little-endian f32 files, written by src/bench/primary/embree.rs:

    triangles.f32   n triangles × 3 corners × (x, y, z), in the scene's order
    origins.f32     m rays × (x, y, z)
    directions.f32  m rays × (x, y, z), of length 1, so t is a distance

One thread. The script builds Embree's scene (not timed: the commit happens
in an untimed call on one ray), then times `EmbreeScene.run` on all the
rays, RUNS times: one call, one thread (embreex loops over the rays with
rtcIntersect1, the single-ray query, in C). It prints one line per run,
`seconds S cpu C`: the wall time and the process's CPU time (no more than
the wall time if one thread did the work), and writes the hit distance of
every ray of the last run to FOLDER/t.f32 (f32, +inf where the ray hits
nothing), for raybook to compare.

PROCESSES at once (only if PROCESSES > 1). raybook also traces the rays on
PROCESSES threads; where a machine's cores slow each other down (as
hyperthreads sharing a core do), one thread's throughput is not what each
of them gets when all are busy. So that Embree is measured under the same
contention, the script also traces the rays in PROCESSES worker processes
at once: processes, not threads, so that no lock of Python's (its GIL) can
make them take turns (embreex 4.4 does release the GIL in its C loop, but
processes need no such promise). Each worker builds and commits its
own scene (not timed), then, RUNS times, all wait at a barrier and each
traces its share of the rays: blocks of BLOCK rays (a quarter of a
1024-pixel row) dealt out in turn, so that every share holds parts of
every region of the image and the shares cost alike (split into PROCESSES
contiguous runs, the share with the busier rows took 1.2 to 1.4 times as
long as the other, and the run's time was that share's). raybook's threads
share out their work as they go, so this is the fair comparison. Each worker notes when its call starts and ends, on
the system-wide CLOCK_MONOTONIC, so that the clocks of the processes can
be compared; a run's time is from the first start to the last end: the
time the rays took with every worker busy while any was. It prints one
line per run, `parallel N seconds S cpu C busy B1 .. BN`: N the workers, S
that time, C the CPU time the workers used in their calls (no more than
N × S if each used one thread), and each worker's own time, which shows
how unevenly the shares cost. The workers' answers must be the one
thread's, or the script fails. The workers are started before this
process creates an Embree device: Embree's thread pool (TBB) does not
survive a fork.

`python3 embree_primary.py --check` exits 0 if embreex and numpy can be
imported, and prints embreex's version.
"""

import multiprocessing
import queue
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


def read_scene(folder):
    """The triangles, origins and directions in FOLDER."""
    triangles = read(folder, "triangles.f32", (-1, 3, 3))
    origins = read(folder, "origins.f32", (-1, 3))
    directions = read(folder, "directions.f32", (-1, 3))
    return triangles, origins, directions


def committed_scene(triangles, origins, directions):
    """Embree's scene of the triangles, its BVH built."""
    from embreex.mesh_construction import TriangleMesh
    from embreex.rtcore_scene import EmbreeScene

    scene = EmbreeScene()
    TriangleMesh(scene, triangles)
    # The first query commits the scene: Embree builds its BVH there.
    scene.run(origins[:1], directions[:1])
    return scene


def distances(hits):
    """Each ray's hit distance, +inf for a miss, as little-endian f32."""
    import numpy as np

    return np.where(hits["primID"] >= 0, hits["tfar"], np.inf).astype("<f4")


def one_thread(folder, runs):
    """Times RUNS calls on all the rays in this process; their distances."""
    triangles, origins, directions = read_scene(folder)
    scene = committed_scene(triangles, origins, directions)
    for _ in range(runs):
        start, cpu = time.perf_counter(), time.process_time()
        hits = scene.run(origins, directions, output=1)
        seconds = time.perf_counter() - start
        cpu = time.process_time() - cpu
        print(f"seconds {seconds:.9f} cpu {cpu:.9f}", flush=True)
    return distances(hits)


def now():
    """Seconds on a clock every process on the machine shares."""
    return time.clock_gettime(time.CLOCK_MONOTONIC)


def worker(folder, runs, number, share, barrier, results):
    """One worker process: traces its share (the indices of its rays) RUNS
    times, each time once all workers are ready, and puts its (start, end,
    cpu) of each run and its last run's distances into `results`, or what
    went wrong, as text (an exception may lose its details when pickled)."""
    try:
        triangles, origins, directions = read_scene(folder)
        origins, directions = origins[share], directions[share]
        scene = committed_scene(triangles, origins, directions)
        times = []
        for _ in range(runs):
            barrier.wait()
            start, cpu = now(), time.process_time()
            hits = scene.run(origins, directions, output=1)
            times.append((start, now(), time.process_time() - cpu))
        results.put((number, times, distances(hits)))
    except BaseException as error:
        barrier.abort()  # so that no other worker waits for this one
        results.put((number, f"{type(error).__name__}: {error}", None))


BLOCK = 256


def shares(rays, processes):
    """The indices of the rays, dealt out to `processes` shares in blocks of
    BLOCK: block i goes to share i mod processes."""
    import numpy as np

    block = np.arange(rays) // BLOCK
    return [np.flatnonzero(block % processes == k) for k in range(processes)]


def collect(workers, results):
    """Each worker's result, in the order of their shares; fails if one
    failed or died."""
    answers = []
    while len(answers) < len(workers):
        try:
            answers.append(results.get(timeout=1))
        except queue.Empty:  # no answer this second: is one dead?
            if any(w.exitcode not in (None, 0) for w in workers):
                sys.exit("an Embree worker process died")
    failures = [times for _, times, _ in answers if isinstance(times, str)]
    if failures:
        sys.exit("Embree's worker processes failed: " + "; ".join(failures))
    return sorted(answers, key=lambda answer: answer[0])


def in_processes(folder, runs, processes):
    """Times RUNS runs of `processes` workers tracing a share of the rays
    each, and prints a line per run; the distances of the last run."""
    import numpy as np

    rays = np.fromfile(folder / "origins.f32", dtype="<f4").size // 3
    fork = multiprocessing.get_context("fork")
    barrier, results = fork.Barrier(processes), fork.Queue()
    # Daemons: if one worker dies, the others, waiting for it at the
    # barrier, end when this process does.
    dealt = shares(rays, processes)
    workers = [
        fork.Process(
            target=worker,
            args=(folder, runs, number, share, barrier, results),
            daemon=True,
        )
        for number, share in enumerate(dealt)
    ]
    for w in workers:
        w.start()
    answers = collect(workers, results)
    for w in workers:
        w.join()
    for run in range(runs):
        starts, ends, cpus = zip(*(times[run] for _, times, _ in answers))
        busy = " ".join(f"{end - start:.9f}" for start, end in zip(starts, ends))
        print(
            f"parallel {processes} seconds {max(ends) - min(starts):.9f} "
            f"cpu {sum(cpus):.9f} busy {busy}",
            flush=True,
        )
    t = np.empty(rays, dtype="<f4")
    for share, (_, _, found) in zip(dealt, answers):
        t[share] = found
    return t


def main(folder, runs, processes):
    # The workers first: this process has no Embree device yet to fork.
    parallel = in_processes(folder, runs, processes) if processes > 1 else None
    t = one_thread(folder, runs)
    if parallel is not None and not (parallel == t).all():
        sys.exit("the worker processes found other hits than one thread")
    t.tofile(folder / "t.f32")


if __name__ == "__main__":
    if sys.argv[1:] == ["--check"]:
        check()
    else:
        processes = int(sys.argv[3]) if len(sys.argv) > 3 else 1
        main(Path(sys.argv[1]), int(sys.argv[2]), processes)
