"""Unit tests of the benchmark scripts (bench/): scene generators and their .scn twins, PPM reading, the ground
truth's box filter, Pareto fronts, the radiosity bench's settings injection and summary, and the bench's summary of failed runs. No renderer is run; fast."""
import array
import math
import os
import subprocess
import sys
import tempfile
import unittest

BENCH = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "bench")
sys.path.insert(0, BENCH)

import bench_scenes  # noqa: E402
import bench_tools  # noqa: E402
import pareto  # noqa: E402
import radiosity_pareto  # noqa: E402
import run_bench  # noqa: E402
import specialisation_gain  # noqa: E402

ANCHOR = "/work/shared/perf-anchor/gen_scenes.py"


class SceneTests(unittest.TestCase):
    def test_grid_twin_has_the_same_spheres(self):
        pov = bench_scenes.grid_scene_text(100)
        scn = bench_scenes.grid_scn_text(100)
        pov_spheres = [line for line in pov.splitlines() if line.startswith("sphere")]
        scn_lines = scn.splitlines()
        start = scn_lines.index("spheres 100") + 1
        scn_spheres = scn_lines[start:]
        self.assertEqual(len(pov_spheres), 100)
        self.assertEqual(len(scn_spheres), 100)
        for p, s in zip(pov_spheres, scn_spheres):
            x, y, z, r, tex = s.split()
            self.assertEqual(p, f"sphere {{ <{x}, {y}, {z}>, {r} texture {{ {tex} }} }}")

    def test_no_shadow_grid_marks_every_object(self):
        text = specialisation_gain.no_shadow_text(bench_scenes.grid_scene_text(100))
        objects = [line for line in text.splitlines() if line.startswith(("sphere", "plane"))]
        self.assertEqual(len(objects), 101)
        for line in objects:
            self.assertTrue(line.endswith(" no_shadow }"), line)
        self.assertEqual(text.count("light_source"), 2)

    def test_grid_of_100000_is_not_a_square(self):
        side, spheres = bench_scenes.grid_spheres(100000)
        self.assertEqual(side, 317)
        self.assertEqual(len(spheres), 100000)

    def test_torus_triangle_counts(self):
        verts, tris = bench_scenes.torus_mesh(50)
        self.assertEqual(len(tris), 10000)
        self.assertEqual(bench_scenes.torus_triangles(158), 99856)
        self.assertEqual(bench_scenes.torus_triangles(500), 1000000)
        self.assertTrue(all(v[1] > 0 for v in verts), "the torus rests above the floor plane")
        self.assertTrue(all(len(set(t)) == 3 for t in tris), "no degenerate triangle")

    def test_mesh_and_mesh2_share_one_geometry(self):
        _, scn = bench_scenes.SCENES["mesh_10000"].texts()
        _, scn2 = bench_scenes.SCENES["mesh2_10000"].texts()
        self.assertEqual(scn.splitlines()[1:], scn2.splitlines()[1:])

    @unittest.skipUnless(os.path.exists(ANCHOR), "perf-anchor generator not on this machine")
    def test_anchor_scenes_are_byte_identical(self):
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([sys.executable, ANCHOR, "--outdir", tmp, "--only", "mesh_10000", "mesh2_10000", "glass"],
                           check=True, stderr=subprocess.DEVNULL)
            for ours, theirs in (("mesh_10000", "mesh_10000"), ("mesh2_10000", "mesh2_10000"),
                                 ("glass_anchor", "glass")):
                pov, scn = bench_scenes.SCENES[ours].texts()
                with open(os.path.join(tmp, theirs + ".pov")) as f:
                    self.assertEqual(pov, f.read(), ours)
                if theirs != "mesh2_10000":   # gen_scenes.py keeps one .scn for both mesh forms
                    with open(os.path.join(tmp, theirs + ".scn")) as f:
                        self.assertEqual(scn, f.read(), ours)

    def test_every_render_scene_says_whether_it_has_a_twin(self):
        for name in run_bench.SUITE:
            spec = bench_scenes.SCENES[bench_scenes.base_scene(name)]
            self.assertTrue(spec.has_twin or spec.no_twin, name)

    def test_write_scene_writes_twin_only_when_there_is_one(self):
        with tempfile.TemporaryDirectory() as tmp:
            pov, scn = bench_scenes.write_scene("grid_100", tmp)
            self.assertTrue(os.path.exists(pov) and os.path.exists(scn))
            pov, scn = bench_scenes.write_scene("glass", tmp)
            self.assertTrue(os.path.exists(pov))
            self.assertIsNone(scn)


class SuiteTests(unittest.TestCase):
    def test_sets(self):
        self.assertTrue(set(run_bench.QUICK) <= set(run_bench.DEFAULT) <= set(run_bench.SUITE))
        self.assertFalse(set(run_bench.SLOW) & set(run_bench.DEFAULT))
        for base in run_bench.SUITE_BASES:
            self.assertIn(base + "_aa", run_bench.SUITE)
        self.assertEqual(run_bench.quality_switches("glass_aa"), ["+A0.3", "+R3", "-J"])
        self.assertEqual(run_bench.quality_switches("glass"), ["-A"])

    def test_old_names_still_accepted(self):
        args = run_bench.parse_args(["--only", "showcase_aa", "grid_10000_aa", "glass_aa", "mesh_1m", "parse_while"])
        self.assertEqual(run_bench.selected_names(args)[0], "showcase_aa")

    def test_embree_result_line(self):
        out = "noise\nRESULT scene=a.scn threads=2 render_min_s=0.5 render_med_s=0.625 build_s=0.01\n"
        fields = run_bench.parse_embree_result(out)
        self.assertEqual(fields["render_med_s"], 0.625)
        self.assertEqual(fields["scene"], "a.scn")
        self.assertIsNone(run_bench.parse_embree_result("embree error 3: bad"))

    def test_a_failed_program_is_recorded_not_hidden(self):
        args = run_bench.parse_args(["--reps", "2"])
        ok = {"tool": "povray", "ok": True, "rc": 0, "wall_s": 1.0, "peak_kb": 2048, "parse_s": 0.1, "build_s": 0.0,
              "render_s": 0.5, "total_s": None, "rays": None, "error": None}
        bad = run_bench.failed_run("povtrace", "exit status 1: parse error")
        row = run_bench.summarize("grid_100", [ok, dict(ok, render_s=0.7), bad, bad], None, "n/a", args)
        self.assertEqual(row["povtrace_ok"], "0/2")
        self.assertEqual(row["povray_ok"], "2/2")
        self.assertAlmostEqual(row["povray_render_s_median"], 0.6)
        self.assertIsNone(row["ratio_render_median"])
        self.assertIn("parse error", row["errors"])
        run_bench.add_embree(row, {})
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "t.md")
            run_bench.write_markdown(path, [row], ["header"], args, [], "")
            with open(path) as f:
                text = f.read()
        self.assertIn("| grid_100 | 0/2 | 2/2 |", text)
        self.assertIn("- grid_100: exit status 1: parse error", text)

    def test_replot_reads_the_summary_back(self):
        args = run_bench.parse_args(["--reps", "1"])
        ok = {"tool": "povray", "ok": True, "rc": 0, "wall_s": 1.0, "peak_kb": 2048, "parse_s": 0.001,
              "build_s": 0.0, "render_s": 0.5, "total_s": None, "rays": None, "error": None}
        row = run_bench.summarize("mesh2_10000", [ok, dict(ok, tool="povtrace", rays=10)], 101.5, "pass", args)
        run_bench.add_embree(row, {})
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "latest.csv")
            with open(path, "w", newline="") as f:
                w = run_bench.csv.DictWriter(f, fieldnames=list(row.keys()))
                w.writeheader()
                w.writerow(row)
            back = run_bench.read_rows(path)[0]
        self.assertEqual(back["scene"], "mesh2_10000")
        self.assertEqual(back["primitives"], 10000)
        self.assertEqual(back["povtrace_ok"], "1/1")
        self.assertAlmostEqual(back["psnr_db"], 101.5)
        self.assertIsNone(back["embree_render_s_median"])
        self.assertFalse(run_bench.meaningful_parse(back), "1 ms parses give no parse ratio in the plot")

    def test_no_plot_panel_without_data(self):
        rows = [{"scene": "a", "povtrace_render_s_median": None}]
        self.assertIsNone(run_bench.scene_bars_script("x.png", run_bench.SCENE_PANELS["latest_times.png"], rows,
                                                      "d.dat", ["povtrace_render_s_median"], ""))


class ImageTests(unittest.TestCase):
    def write_ppm(self, path, width, height, maxval, samples):
        with open(path, "wb") as f:
            f.write(f"P6\n# comment\n{width} {height}\n{maxval}\n".encode())
            if maxval < 256:
                f.write(bytes(samples))
            else:
                f.write(b"".join(v.to_bytes(2, "big") for v in samples))

    def test_read_ppm_8_and_16_bit(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "a.ppm")
            self.write_ppm(path, 2, 1, 255, [0, 10, 255, 1, 2, 3])
            self.assertEqual(bench_tools.read_ppm(path)[3].tolist(), [0, 10, 255, 1, 2, 3])
            self.write_ppm(path, 1, 2, 65535, [0, 258, 65535, 1, 2, 3])
            w, h, m, s = bench_tools.read_ppm(path)
            self.assertEqual((w, h, m, s.tolist()), (1, 2, 65535, [0, 258, 65535, 1, 2, 3]))

    def test_box_filter_averages_in_linear_light(self):
        maxval = 65535
        white, black = maxval, 0
        # 4x2 image, factor 2: left block half white, half black; right block all black.
        row = [white] * 3 + [black] * 3 + [black] * 6
        samples = array.array("H", row + row)
        w, h, values, mixed = pareto.box_filter(4, 2, maxval, samples, 2)
        self.assertEqual((w, h), (2, 1))
        self.assertAlmostEqual(values[0], pareto.srgb_encode(0.5), places=6)   # not 0.5: averaged in linear light
        self.assertEqual(values[3:], [0.0, 0.0, 0.0])
        self.assertEqual(mixed, 0.5)

    def test_srgb_round_trip_and_psnr(self):
        for v in (0.0, 0.002, 0.2, 0.7, 1.0):
            self.assertAlmostEqual(pareto.srgb_decode(pareto.srgb_encode(v)), v, places=9)
        self.assertAlmostEqual(pareto.psnr(0.01), 40.0)
        self.assertTrue(math.isinf(pareto.psnr(0.0)))
        self.assertAlmostEqual(pareto.rmse([0, 0, 0, 0], [1, 1, 0, 0]), math.sqrt(0.5))


class ParetoTests(unittest.TestCase):
    def test_front(self):
        points = [(1.0, 0.5), (2.0, 0.2), (2.0, 0.3), (3.0, 0.2), (0.5, 0.9), (4.0, 0.1)]
        self.assertEqual(pareto.pareto_front(points), [4, 0, 1, 5])

    def test_equal_points_are_both_on_the_front(self):
        self.assertEqual(pareto.pareto_front([(1.0, 0.5), (1.0, 0.5)]), [0, 1])

    def test_coverage_and_speedup(self):
        ours = [(0.5, 0.5), (1.0, 0.2)]
        theirs = [(1.0, 0.5), (2.0, 0.2), (3.0, 0.1)]
        self.assertEqual(pareto.front_coverage(ours, theirs), 2)
        self.assertEqual(pareto.speedup_at_equal_error(ours, theirs), [2.0, 2.0, None])

    def test_equal_error_allows_rounding_between_renderers(self):
        ours = [(0.2, 0.0076167), (2.0, 0.003)]
        theirs = [(0.4, 0.0076166)]
        self.assertEqual(pareto.speedup_at_equal_error(ours, theirs), [2.0])
        self.assertEqual(pareto.front_coverage(ours, theirs), 1)
        self.assertEqual(pareto.front_coverage([(0.2, 0.0078)], theirs), 0)   # 2.4 % worse is worse

    def test_verdict(self):
        rows = []
        for tool, pts in (("povtrace", [(0.5, 0.5), (1.0, 0.2)]), ("povray", [(1.0, 0.5), (2.0, 0.2)])):
            for t, e in pts:
                rows.append({"scene": "s", "renderer": tool, "on_front": True, "render_s_min": t, "rmse": e,
                             "psnr_db": pareto.psnr(e), "setting": "x"})
        lines, verdict = pareto.scene_summary("s", rows)
        self.assertEqual(verdict, "povtrace's front dominates POV-Ray's")
        self.assertIn("Speed at equal or lower error: 2.00–2.00", "\n".join(lines))

    def test_aa_switches(self):
        self.assertEqual(pareto.aa_switches((0, 0.0, 0)), ["-A"])
        self.assertEqual(pareto.aa_switches((2, 0.05, 4)), ["+AM2", "+A0.05", "+R4", "-J"])
        self.assertEqual(pareto.aa_switches((1, 0, 3)), ["+AM1", "+A0.0", "+R3", "-J"])   # POV-Ray rejects +A0


class RadiosityParetoTests(unittest.TestCase):
    POV_STATS = ("Render Time:\n  Photon Time:      No photons\n"
                 "  Radiosity Time:   0 hours  0 minutes  6 seconds (6.315 seconds)\n"
                 "  Trace Time:       0 hours  0 minutes  0 seconds (0.317 seconds)\n")

    def test_povray_times_are_pretrace_and_final_pass(self):
        self.assertEqual(radiosity_pareto.povray_render_times(self.POV_STATS), (6.315, 0.317))
        self.assertEqual(radiosity_pareto.povray_render_times("  Radiosity Time:   No radiosity\n"), (None, None))

    def test_override_is_appended_and_names_only_the_set_items(self):
        setting = {"count": 20.0, "error_bound": 1.8, "pretrace_end": None, "nearest_count": None}
        with tempfile.TemporaryDirectory() as d:
            src = os.path.join(d, "s.pov")
            with open(src, "w") as f:
                f.write("global_settings { radiosity { pretrace_start 0.04 // pretrace_start 9\n count 200 } }\n")
            path = radiosity_pareto.write_scene_copy(src, setting, d, "copy")
            with open(path) as f:
                text = f.read()
            self.assertTrue(text.startswith("global_settings { radiosity { pretrace_start 0.04"))
            self.assertTrue(text.endswith("global_settings { radiosity { count 20 error_bound 1.8 } }\n"))
            self.assertEqual(radiosity_pareto.pretrace_start_of(src), 0.04)   # the comment is not read
        self.assertEqual(radiosity_pareto.setting_label(dict(setting, nearest_count=20.0)), "count 20 eb 1.8 nc 20")

    def test_sweep_is_the_product_of_the_lists(self):
        args = radiosity_pareto.parse_args(["--counts", "20", "50", "--error-bounds", "1", "--nearest-counts", "5",
                                            "10"])
        self.assertEqual(len(radiosity_pareto.sweep(args)), 4)
        self.assertTrue(all(s["pretrace_end"] is None for s in radiosity_pareto.sweep(args)))

    def test_summary_matches_each_povray_front_point(self):
        rows = []
        for tool, pts in (("povtrace", [(0.5, 0.5), (1.0, 0.2), (0.7, 0.6)]),
                          ("povray", [(1.0, 0.5), (2.0, 0.2), (3.0, 0.1)])):
            for t, e in pts:
                rows.append({"scene": "s", "renderer": tool, "render_s_min": t, "rmse": e,
                             "psnr_db": pareto.psnr(e), "setting": f"{tool} {t}"})
        radiosity_pareto.mark_fronts(rows)
        self.assertEqual([r["on_front"] for r in rows], [True, True, False, True, True, True])
        lines, verdict = radiosity_pareto.scene_summary("s", rows)
        text = "\n".join(lines)
        self.assertTrue(verdict.startswith("neither front dominates the other; speed at equal or lower error 2.00–2.00"))
        self.assertIn("| povray 1.0 | 1.000 | 6.02 | povtrace 0.5 | 0.500 | 6.02 | 2.00 |", text)
        self.assertIn("| povray 3.0 | 3.000 | 20.00 | none as accurate |", text)
        self.assertIn("Speed at equal or lower error 2.00–2.00 over the 2 matched POV-Ray front points (1 unmatched)",
                      text)


if __name__ == "__main__":
    unittest.main()
