"""`import rayo` (apps/python/rayo_module.cpp, docs/python.md), run in one interpreter so that
state left by one render would show in the next. ctest runs this file with PYTHONPATH set to the
build's python/ folder and RAYO_CLI to the rayo executable (CMakeLists.txt)."""

import math
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import rayo

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLI = os.environ.get("RAYO_CLI", os.path.join(REPO, "build", "rayo"))
GLASS = os.path.join(REPO, "scenes", "glass.json")

NFF = textwrap.dedent("""\
    v
    from 0 0 5
    at 0 0 0
    up 0 1 0
    angle 40
    hither 0.01
    resolution 48 32
    b 0.2 0.3 0.5
    l 3 3 3
    f 1 0 0 0.8 0.2 20 0.5 1
    s 0 0 0 1
    f 0.9 0.9 0.9 0.8 0.0 1 0 1
    p 4
    -3 -1 -3
    3 -1 -3
    3 -1 3
    -3 -1 3
    """)


def cli(*args, cwd=None):
    return subprocess.run([CLI, *args], cwd=cwd, capture_output=True, text=True)


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return str(path)


# --- scenes -------------------------------------------------------------------------------------

def test_load_reads_every_format_the_cli_reads(tmp_path):
    files = {
        "s.nff": NFF,
        "s.json": '{"rayo": 1, "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "width": 8,'
                  ' "height": 8}, "objects": [{"type": "sphere", "center": [0, 0, 0],'
                  ' "radius": 1}]}',
        "s.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "s.ply": "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "s.stl": "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                 "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n",
        "s.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        # One triangle, its positions in a data URI (9 floats).
        "s.gltf": '{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],'
                  ' "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],'
                  ' "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3,'
                  ' "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],'
                  ' "bufferViews": [{"buffer": 0, "byteLength": 36}],'
                  ' "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,'
                  'AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}',
    }
    for name, text in files.items():
        scene = rayo.load(write(tmp_path / name, text))
        counts = scene.counts
        if name in ("s.nff", "s.json"):
            assert counts["spheres"] == 1, name
        else:
            # The model's triangle (model files get a ground square too: 2 more).
            assert counts["triangles"] in (1, 3), (name, counts)
        image, _ = rayo.render(scene, width=16)
        assert image.shape[1] == 16 and image.shape[2] == 4
    # The built-in scene without a path, as `rayo render` without a scene.
    assert rayo.load().source == "<default>"


def test_a_scene_shows_what_it_holds_as_rayo_info_does(tmp_path):
    scene = rayo.load(write(tmp_path / "s.nff", NFF))
    assert scene.camera["width"] == 48 and scene.camera["height"] == 32
    assert scene.camera["eye"] == (0.0, 0.0, 5.0)
    h, v = scene.camera["fov"]
    assert math.tan(math.radians(h / 2)) / math.tan(math.radians(v / 2)) == pytest.approx(48 / 32)
    assert scene.counts["spheres"] == 1 and scene.counts["lights"] == 1
    assert scene.lights[0].startswith("point position 3 3 3")
    (lo, hi) = scene.bounds
    assert lo == (-3.0, -1.0, -3.0) and hi == (3.0, 1.0, 3.0)
    info = cli("info", str(tmp_path / "s.nff")).stdout
    assert f"light 0 {scene.lights[0]}\n" in info
    assert scene.settings["integrator"] == "whitted"


def test_from_dict_and_from_json_validate_as_a_file_is():
    d = {"rayo": 1, "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "width": 8, "height": 8},
         "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]}
    with pytest.raises(rayo.InputError) as e:
        rayo.Scene.from_dict(d)
    assert "<dict>#/objects/0/radius" in str(e.value)
    d["objects"][0]["radius"] = 1
    scene = rayo.Scene.from_dict(d)
    assert scene.counts["spheres"] == 1
    with pytest.raises(rayo.InputError) as e:
        rayo.Scene.from_json('{"rayo": 1, "camera": ', name="broken.json")
    assert "broken.json:1:" in str(e.value)


def test_errors_name_the_place(tmp_path):
    bad = write(tmp_path / "bad.nff", NFF.replace("s 0 0 0 1", "s 0 0 zero 1"))
    with pytest.raises(rayo.InputError) as e:
        rayo.load(bad)
    assert "bad.nff:11" in str(e.value)
    with pytest.raises(rayo.InputError) as e:
        rayo.load(str(tmp_path / "missing.json"))
    assert "missing.json" in str(e.value)
    # The CLI says the same of the same file.
    with pytest.raises(rayo.InputError) as e:
        rayo.load(bad)
    r = cli("render", bad, "-o", str(tmp_path / "x.png"))
    assert r.returncode == 1 and r.stderr == f"rayo: error: {e.value}\n"


# --- keywords: the command line's options -------------------------------------------------------

def test_keywords_take_the_command_lines_names_bounds_and_messages(tmp_path):
    scene = rayo.load(GLASS)
    for keyword, value, flag in [("spp", 0, "--spp"), ("max_depth", 1000, "--max-depth"),
                                 ("sphere_method", "mesh:9", "--sphere-method"),
                                 ("width", 0, "--width"), ("integrator", "magic", "--integrator")]:
        with pytest.raises(rayo.UsageError) as e:
            rayo.render(scene, **{keyword: value})
        r = cli("render", GLASS, flag, str(value), "-o", str(tmp_path / "x.png"))
        assert r.returncode == 2
        assert r.stderr == f"rayo: error: {e.value}\n", keyword
    with pytest.raises(TypeError, match="unexpected keyword argument 'spp_count'"):
        rayo.render(scene, spp_count=2)
    with pytest.raises(TypeError, match="'view_dir' is an option of rayo.load"):
        rayo.render(scene, view_dir=(0, 0, 1))
    with pytest.raises(TypeError, match="'half' is an option of rayo.write"):
        rayo.render(scene, half=True)
    with pytest.raises(TypeError, match="'resume' is an option of the command line only"):
        rayo.render(scene, resume=True)
    with pytest.raises(rayo.UsageError, match="a switch"):
        rayo.render(scene, single_rays="yes")
    keywords = {o["keyword"]: o for o in rayo.options()}
    assert keywords["spp"]["function"] == "rayo.render"
    assert keywords["view_dir"]["function"] == "rayo.load"
    assert keywords["exr_compression"]["function"] == "rayo.write"
    assert keywords["single_rays"]["switch"] and not keywords["spp"]["switch"]
    assert "ao_samples" in keywords and "resume" not in keywords


def test_an_image_rendered_through_python_is_the_clis_bit_for_bit(tmp_path):
    nff = write(tmp_path / "s.nff", NFF)
    cases = [
        (GLASS, {"width": 64}, ["--width", "64"]),
        (nff, {"spp": 3, "sphere_method": "mesh:2", "single_rays": True},
         ["--spp", "3", "--sphere-method", "mesh:2", "--single-rays"]),
        (nff, {"integrator": "path", "spp": 2, "max_depth": 3},
         ["--integrator", "path", "--spp", "2", "--max-depth", "3"]),
        (nff, {"integrator": "ambient_occlusion", "ao_samples": 4, "threads": 1},
         ["--integrator", "ambient_occlusion", "--ao-samples", "4", "--threads", "1"]),
    ]
    for i, (path, keywords, flags) in enumerate(cases):
        out = str(tmp_path / f"cli{i}.exr")
        r = cli("render", path, *flags, "-o", out, "--quiet")
        assert r.returncode == 0, r.stderr
        image, stats = rayo.render(rayo.load(path), **keywords)
        assert image.dtype == np.float32
        assert np.array_equal(image, rayo.read(out)), (path, keywords)
        assert stats["width"] == image.shape[1] and stats["rays"]["camera"] > 0


def test_renders_in_one_process_stay_independent(tmp_path):
    nff = rayo.load(write(tmp_path / "s.nff", NFF))
    glass = rayo.load(GLASS)
    first, _ = rayo.render(glass, width=40)
    rayo.render(nff, integrator="path", spp=2)
    rayo.render(nff, sphere_method="mesh:1", flat_spheres=True, texture_cache=8)
    again, stats = rayo.render(glass, width=40)
    assert np.array_equal(first, again)
    # The scene itself is not changed by a render's options.
    assert glass.camera["width"] == 320 and glass.settings["spp"] == "1"
    assert stats["sphere_method"] == "user"


def test_stats_say_what_ran():
    _, stats = rayo.render(rayo.load(GLASS), width=32, sphere_method="bruteforce", threads=1)
    assert stats["sphere_method"] == "bruteforce"
    assert stats["threads"] == 1
    assert stats["rays"]["total"] == sum(stats["rays"][k] for k in (
        "camera", "shadow", "shadow_filtered", "reflection", "refraction"))
    assert stats["rays"]["camera"] == 32 * 24
    assert stats["render_seconds"] > 0 and stats["mrays_per_second"] > 0


# --- closed forms -------------------------------------------------------------------------------

def test_a_spheres_coverage_is_its_projected_disc():
    # A unit sphere 4 away: its silhouette is a circle of angular radius asin(1/4); on the
    # window one unit before the eye, of radius tan(asin(1/4)). Lit by the ambient term alone
    # (ka 1, ambient 1) before black, a pixel's value is its coverage.
    vfov = 40.0
    size = 256
    d = {"rayo": 1, "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "vfov": vfov,
                               "width": size, "height": size},
         "render": {"spp": 16}, "background": 0, "ambient_light": 1,
         "materials": {"flat": {"ka": 1, "kd": 0, "ks": 0}},
         "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "flat"}]}
    image, _ = rayo.render(rayo.Scene.from_dict(d))
    half = math.tan(math.radians(vfov / 2))
    disc = math.pi * math.tan(math.asin(1 / 4)) ** 2
    expected = disc / (2 * half) ** 2
    assert image[..., 0].mean() == pytest.approx(expected, rel=2e-3)


def test_a_diffuse_sphere_under_a_uniform_sky_reflects_its_albedo():
    # Path tracing, a convex Lambertian sphere of albedo 0.5 under a uniform environment of
    # radiance 1: every reflected ray escapes, so L = 0.5 on the sphere and 1 beside it.
    d = {"rayo": 1, "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "vfov": 30,
                               "width": 64, "height": 64},
         "render": {"spp": 64, "integrator": {"type": "path", "max_depth": 16}},
         "environment": {"color": 1},
         "materials": {"grey": {"kd": 0.5, "ks": 0}},
         "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "grey"}]}
    image, stats = rayo.render(rayo.Scene.from_dict(d))
    assert stats["integrator"].startswith("path")
    inside = image[16:48, 16:48, :3]  # the sphere's disc has a radius of 30.8 pixels
    assert inside.mean() == pytest.approx(0.5, rel=0.01)
    assert np.all(image[0, 0] == 1.0) and np.all(image[63, 63] == 1.0)


# --- images -------------------------------------------------------------------------------------

def test_write_uses_the_clis_writers_and_views(tmp_path):
    image, _ = rayo.render(rayo.load(GLASS), width=64)
    rayo.write(image, str(tmp_path / "a.exr"))
    assert np.array_equal(rayo.read(str(tmp_path / "a.exr")), image)
    rayo.write(image, str(tmp_path / "a.png"))
    r = cli("render", GLASS, "--width", "64", "-o", str(tmp_path / "b.png"), "--quiet")
    assert r.returncode == 0
    assert np.array_equal(rayo.read(str(tmp_path / "a.png")), rayo.read(str(tmp_path / "b.png")))
    rayo.write(image, str(tmp_path / "raw.png"), view="Raw")
    assert not np.array_equal(rayo.read(str(tmp_path / "raw.png")),
                              rayo.read(str(tmp_path / "a.png")))
    rayo.write(image, str(tmp_path / "h.exr"), half=True, exr_compression="piz")
    assert np.allclose(rayo.read(str(tmp_path / "h.exr")), image, rtol=1e-3, atol=1e-3)
    rayo.write(image[..., :3], str(tmp_path / "rgb.exr"))
    assert rayo.read(str(tmp_path / "rgb.exr"))[..., 3].min() == 1.0


def test_write_refuses_bad_output_and_leaves_no_file(tmp_path):
    image = np.zeros((4, 4, 4), np.float32)
    with pytest.raises(rayo.InputError):
        rayo.write(image, str(tmp_path / "nowhere" / "a.png"))
    with pytest.raises(rayo.InputError):
        rayo.write(image, str(tmp_path / "a.bmpx"))
    with pytest.raises((rayo.InputError, rayo.UsageError)):
        rayo.write(image, str(tmp_path / "a.png"), view="No Such View")
    with pytest.raises(rayo.UsageError, match="exr-compression"):
        rayo.write(image, str(tmp_path / "a.exr"), exr_compression="lzma")
    with pytest.raises(rayo.UsageError, match="height × width"):
        rayo.write(np.zeros((4, 4), np.float32), str(tmp_path / "a.exr"))
    assert os.listdir(tmp_path) == []


# --- long renders: the interpreter's lock, progress, Ctrl-C ---------------------------------------

def test_progress_is_reported_and_other_threads_run_during_a_render():
    seen = []
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        rayo.render(rayo.load(GLASS), width=640, spp=16, progress=seen.append)
    finally:
        stop.set()
        counter.join()
    assert seen and seen[-1] == 1.0
    assert all(a <= b for a, b in zip(seen, seen[1:]))
    assert ticks[0] > 10  # the lock was released while rendering


def test_ctrl_c_stops_a_render_promptly_and_raises_keyboard_interrupt(tmp_path):
    script = write(tmp_path / "long.py", textwrap.dedent(f"""\
        import sys, rayo
        scene = rayo.load({GLASS!r})
        def started(fraction):
            print("started", flush=True)
        try:
            rayo.render(scene, width=4000, spp=64, progress=started)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            image, _ = rayo.render(scene, width=16)  # the next render runs whole
            print("then", image.shape, flush=True)
            sys.exit(3)
        """))
    env = dict(os.environ)
    p = subprocess.Popen([sys.executable, script], stdout=subprocess.PIPE, text=True, env=env)
    assert p.stdout.readline() == "started\n"
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    assert p.returncode == 3, out
    assert time.monotonic() - sent < 10
    assert "interrupted" in out and "then (12, 16, 4)" in out


# --- studies ------------------------------------------------------------------------------------

def test_the_studies_return_their_tables(tmp_path):
    rows = rayo.bench_suite(str(tmp_path / "suite"), size=1, width=32, scenes=["balls"])
    assert [r["scene"] for r in rows] == ["balls"]
    assert rows[0]["rays"] > 0 and rows[0]["mrays_per_second"] > 0
    assert os.path.exists(tmp_path / "suite" / "suite.csv")
    with pytest.raises(rayo.InputError):
        rayo.bench_suite(scenes=["nonesuch"], width=8)
    rows = rayo.bench_accuracy(str(tmp_path / "accuracy"), size=24)
    assert {r["method"] for r in rows} >= {"user", "bruteforce", "embree-point", "mesh:3"}
    doubles = [r for r in rows if r["math"] == "double"]
    assert doubles and all(r["rmse"] == 0.0 for r in doubles)
    assert os.path.exists(tmp_path / "accuracy" / "accuracy.csv")


def test_the_documented_example_script_runs(tmp_path):
    # docs/python.md's example: every sphere method's time and error, table (and chart).
    script = os.path.join(REPO, "scripts", "python_sphere_methods.py")
    r = subprocess.run([sys.executable, script, "1", "48", str(tmp_path / "chart.png")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    lines = [line for line in r.stdout.splitlines() if "rmse" in line]
    assert len(lines) == 14
    # Brute force in double is the reference; in float its error is small but the silhouettes
    # of mesh:1 are visibly wrong.
    errors = {tuple(line.split()[:2]): float(line.split()[-1]) for line in lines}
    assert errors[("mesh:1", "stable")] > 10 * errors[("user", "stable")]
