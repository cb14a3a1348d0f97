# SPDX-License-Identifier: BSD-3-Clause
"""Tests of the Python binding (bindings/python/surfadapt.py) against the built library.

Plain unittest, no pytest. Run from anywhere with an interpreter that has numpy; the
library is the one SURFADAPT_LIBRARY names, else the tree's lib/ (tests/python/run.sh
sets it). Ends with "python-binding: N passed, M failed", the line scripts/run-tests.sh
counts.
"""
import importlib.util
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir))
sys.path.insert(0, os.path.join(ROOT, "bindings", "python"))
import surfadapt  # noqa: E402


def sphere(subdivisions=3, radius=0.5, center=(0.0, 0.0, 0.0)):
    return surfadapt.icosphere(subdivisions, radius, center)


def triangle_areas(xyz, tris):
    a, b, c = xyz[tris[:, 0]], xyz[tris[:, 1]], xyz[tris[:, 2]]
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def header_constants():
    """Every constant of include/surfadapt.h: the enumerators (NAME = N inside an enum)
    and the numeric #defines of SFA_*."""
    with open(os.path.join(ROOT, "include", "surfadapt.h"), encoding="utf-8") as f:
        text = f.read()
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)  # comments quote constants too
    constants = {}
    for body in re.findall(r"\benum\s+\w+\s*\{(.*?)\}", text, flags=re.S):
        for name, value in re.findall(r"\b(SFA_\w+)\s*=\s*(\d+)", body):
            constants[name] = int(value)
    for name, value in re.findall(r"^\s*#\s*define\s+(SFA_\w+)\s+(\d+)\s*$", text, flags=re.M):
        constants[name] = int(value)
    return constants


class Constants(unittest.TestCase):
    def test_every_header_constant_is_in_the_module_with_its_value(self):
        header = header_constants()
        self.assertGreater(len(header), 50, "the header parser found too few constants")
        for name, value in header.items():
            self.assertTrue(hasattr(surfadapt, name), f"surfadapt.py lacks {name} (= {value} in the header)")
            self.assertEqual(int(getattr(surfadapt, name)), value, name)
        module = {n for n in dir(surfadapt) if n.startswith("SFA_")}
        self.assertEqual(module - set(header), set(), "constants of the module that the header does not have")

    def test_versions_of_the_library_loaded(self):
        self.assertEqual(surfadapt.abi_version(), surfadapt.SFA_ABI_VERSION)
        self.assertEqual(surfadapt.version(), "%d.%d.%d" % (surfadapt.SFA_VERSION_MAJOR, surfadapt.SFA_VERSION_MINOR,
                                                            surfadapt.SFA_VERSION_PATCH))
        self.assertEqual(surfadapt.version_number(), surfadapt.SFA_VERSION_MAJOR * 10000
                         + surfadapt.SFA_VERSION_MINOR * 100 + surfadapt.SFA_VERSION_PATCH)
        self.assertIn("SFA_ERR_MESH", surfadapt.status_string(surfadapt.SFA_ERR_MESH))


class MeshInOut(unittest.TestCase):
    def test_round_trip_is_exact_in_both_index_bases(self):
        xyz, tris = sphere()
        with surfadapt.Surface(xyz, tris) as s:
            self.assertEqual(s.counts, (642, 1280))
            out_xyz, out_tris = s.mesh()
            self.assertEqual(out_xyz.dtype, np.float64)
            self.assertEqual(out_tris.dtype, np.int32)
            np.testing.assert_array_equal(out_xyz, xyz)
            np.testing.assert_array_equal(out_tris, tris)
            np.testing.assert_array_equal(s.mesh(index_base=1)[1], tris + 1)
            # Lists, Fortran order and other dtypes are converted.
            s.set_mesh(np.asfortranarray(xyz).astype(np.float32).tolist(), (tris + 1).astype(np.int64), index_base=1)
            np.testing.assert_array_equal(s.mesh()[1], tris)
            np.testing.assert_array_equal(s.mesh()[0], xyz.astype(np.float32))

    def test_a_bad_mesh_raises_the_library_message_and_changes_nothing(self):
        xyz, tris = sphere()
        with surfadapt.Surface(xyz, tris) as s:
            bad = tris.copy()
            bad[17, 1] = 700
            with self.assertRaises(surfadapt.MeshError) as caught:
                s.set_mesh(xyz, bad)
            e = caught.exception
            self.assertEqual(e.status, surfadapt.SFA_ERR_MESH)
            self.assertEqual(e.function, "sfa_set_mesh")
            self.assertIn("triangle 17", str(e))
            self.assertIn("vertex 700", str(e))
            self.assertIsInstance(e, surfadapt.SurfadaptError)
            self.assertIsInstance(e, ValueError)
            self.assertEqual(s.counts, (642, 1280))  # nothing lost
            np.testing.assert_array_equal(s.mesh()[1], tris)

    def test_shapes_and_types_are_checked_before_the_library_sees_them(self):
        xyz, tris = sphere(1)
        with surfadapt.Surface() as s:
            with self.assertRaisesRegex(ValueError, r"xyz must have shape \(n, 3\), got \(42, 2\)"):
                s.set_mesh(xyz[:, :2], tris)
            with self.assertRaisesRegex(TypeError, "tris must hold integers"):
                s.set_mesh(xyz, tris + 0.5)
            with self.assertRaisesRegex(ValueError, "outside int32"):
                s.set_mesh(xyz, tris.astype(np.int64) + 2 ** 40)
            with self.assertRaisesRegex(ValueError, "index_base must be 0 or 1"):
                s.set_mesh(xyz, tris, index_base=2)
            with self.assertRaises(surfadapt.StateError) as caught:
                s.adapt()  # no mesh yet: the library's own message
            self.assertIn("sfa_adapt", str(caught.exception))

    def test_close_is_idempotent_and_a_closed_surface_refuses_calls(self):
        s = surfadapt.Surface(*sphere(1))
        self.assertFalse(s.closed)
        s.close()
        s.close()
        self.assertTrue(s.closed)
        self.assertIn("closed", repr(s))
        with self.assertRaisesRegex(surfadapt.StateError, "closed"):
            s.measure("volume")
        del s  # __del__ after close is harmless

    def test_an_unclosed_surface_is_freed_when_collected(self):
        for _ in range(50):
            surfadapt.Surface(*sphere(2))


class Parameters(unittest.TestCase):
    def test_keys_by_member_number_and_name(self):
        with surfadapt.Surface() as s:
            s.set_param(surfadapt.SFA_PARAM_EDGE_LENGTH, 0.1)
            self.assertEqual(s.get_param("edge_length"), 0.1)
            s.set_param("SFA_PARAM_RIDGE_ANGLE", 50)
            self.assertEqual(s.get_param(surfadapt.Param.RIDGE_ANGLE), 50.0)
            self.assertEqual(s.get_param(int(surfadapt.Param.SMALL_ANGLE)), 15.0)
            with self.assertRaisesRegex(ValueError, "unknown parameter 'edge_lenght'"):
                s.set_param("edge_lenght", 1)
            with self.assertRaises(surfadapt.ArgumentError) as caught:
                s.set_param("ridge_angle", 500)
            self.assertIn("SFA_PARAM_RIDGE_ANGLE", str(caught.exception))
            self.assertIn("500", str(caught.exception))
            self.assertEqual(s.get_param("ridge_angle"), 50.0)
            with self.assertRaises(surfadapt.ArgumentError):
                s.get_param(999)  # unknown numbers go to the library, which refuses them
        lo, hi = surfadapt.param_bounds("ridge_angle")
        self.assertEqual((lo, hi), (0.0, 180.0))
        self.assertEqual(surfadapt.param_bounds(surfadapt.SFA_PARAM_EDGE_LENGTH)[1], math.inf)
        with self.assertRaisesRegex(surfadapt.ArgumentError, "sfa_get_param_bounds"):
            surfadapt.param_bounds(999)


class Adaptation(unittest.TestCase):
    def test_adapt_changes_the_counts_and_keeps_the_volume(self):
        with surfadapt.Surface(*sphere(3)) as s:
            v0 = s.measure(surfadapt.Measure.VOLUME)
            self.assertAlmostEqual(v0, 4 / 3 * math.pi * 0.125, delta=0.01)
            s.set_param("edge_length", 0.04)  # finer than the 642-vertex sphere's
            s.adapt()
            nv, nt = s.counts
            self.assertGreater(nv, 1000)
            self.assertEqual(nt, 2 * nv - 4)  # still a closed sphere
            self.assertLess(abs(s.measure("volume") - v0) / v0, 1e-10)
            self.assertEqual(s.measure("self_intersections"), 0)
            self.assertEqual(s.mesh()[0].shape, (nv, 3))
            s.smooth(2)
            self.assertLess(abs(s.measure("volume") - v0) / v0, 1e-10)
            self.assertEqual(s.feature_ranks().shape, (nv,))
            self.assertEqual(s.ridge_edges().shape, (0, 2))  # a sphere has no ridges
            normals, longs, ratios = s.vertex_frames()
            xyz = s.mesh()[0]
            radial = xyz / np.linalg.norm(xyz, axis=1)[:, None]
            self.assertGreater(np.min(np.sum(normals * radial, axis=1)), 0.99)
            triangle, bary = s.vertex_origins()
            self.assertEqual(triangle.shape, (nv,))
            np.testing.assert_allclose(bary.sum(axis=1), 1.0, atol=1e-12)

    def test_two_components(self):
        a_xyz, a_tris = sphere(2, 0.3, (-1, 0, 0))
        b_xyz, b_tris = sphere(2, 0.2, (1, 0, 0))
        with surfadapt.Surface(np.vstack([a_xyz, b_xyz]), np.vstack([a_tris, b_tris + len(a_xyz)])) as s:
            self.assertEqual(s.component_count, 2)
            c = s.components()
            np.testing.assert_array_equal(c, [0] * len(a_xyz) + [1] * len(b_xyz))
            ratio = s.measure_component(0, "volume") / s.measure_component(1, "volume")
            self.assertAlmostEqual(ratio, (0.3 / 0.2) ** 3, places=6)

    def test_fixed_vertices_do_not_move(self):
        xyz, tris = sphere(3)
        with surfadapt.Surface(xyz, tris) as s:
            s.set_fixed_vertices([0, 1, 2])
            s.set_param("edge_length", 0.06)
            s.adapt()
            after = s.mesh()[0]
            for p in xyz[:3]:
                self.assertTrue(np.any(np.all(after == p, axis=1)), f"fixed vertex {p} moved")
            s.set_fixed_vertices([])


class Motion(unittest.TestCase):
    def test_move_with_velocities(self):
        xyz, tris = sphere(2)
        with surfadapt.Surface(xyz, tris) as s:
            v0 = s.measure("volume")
            taken = s.move(np.tile([1.0, -2.0, 0.5], (len(xyz), 1)), 0.1)
            self.assertEqual(taken, 0.1)  # a translation never folds
            np.testing.assert_allclose(s.mesh()[0], xyz + 0.1 * np.array([1.0, -2.0, 0.5]), rtol=0, atol=1e-15)
            self.assertAlmostEqual(s.measure("volume"), v0, delta=1e-12)
            s.move(None, 0.1)  # the velocities set last time
            np.testing.assert_allclose(s.mesh()[0], xyz + 0.2 * np.array([1.0, -2.0, 0.5]), rtol=0, atol=1e-15)
            with self.assertRaisesRegex(ValueError, r"velocities must have shape \(n, 3\)"):
                s.move(np.zeros(len(xyz)), 0.1)

    def test_stale_velocities_after_adapt_are_refused_with_both_counts(self):
        xyz, tris = sphere(2)
        with surfadapt.Surface(xyz, tris) as s:
            s.set_param("edge_length", 0.05)
            s.adapt()
            with self.assertRaises(surfadapt.ArgumentError) as caught:
                s.move(np.zeros_like(xyz), 0.1)
            message = str(caught.exception)
            self.assertIn(str(len(xyz)), message)
            self.assertIn(str(s.nverts), message)

    def test_a_shrinking_sphere_raises_numeric_error_naming_the_fold(self):
        xyz, tris = sphere(2)
        with surfadapt.Surface(xyz, tris) as s:
            s.set_velocities(-xyz / 0.1)  # every vertex reaches the centre at t = 0.1
            with self.assertRaises(surfadapt.NumericError) as caught:
                for _ in range(200):  # the fold control halves each step until it refuses
                    s.move(None, 1.0)
            self.assertEqual(caught.exception.function, "sfa_move")
            self.assertIn("triangle", str(caught.exception))

    def test_advect_with_a_python_callback(self):
        xyz, tris = sphere(2)
        calls = []

        def rotation(points, t):  # rigid rotation about z
            calls.append((points.shape, t))
            return np.column_stack([-points[:, 1], points[:, 0], np.zeros(len(points))])

        with surfadapt.Surface(xyz, tris) as s:
            taken = s.advect(rotation, 0.1, t=2.0)
            self.assertEqual(taken, 0.1)
            self.assertEqual(len(calls), 4)  # RK4: four stages
            self.assertEqual(calls[0], ((len(xyz), 3), 2.0))
            self.assertEqual(calls[-1][1], 2.1)
            c, sn = math.cos(0.1), math.sin(0.1)
            expected = xyz @ np.array([[c, sn, 0], [-sn, c, 0], [0, 0, 1]])
            np.testing.assert_allclose(s.mesh()[0], expected, atol=1e-6)  # RK4's error

    def test_an_exception_in_the_callback_is_raised_after_and_nothing_moves(self):
        xyz, tris = sphere(2)
        with surfadapt.Surface(xyz, tris) as s:
            def broken(points, t):
                raise ZeroDivisionError("the host's own bug")
            with self.assertRaisesRegex(ZeroDivisionError, "the host's own bug") as caught:
                s.advect(broken, 0.1)
            self.assertIsInstance(caught.exception.__cause__, surfadapt.NumericError)
            np.testing.assert_array_equal(s.mesh()[0], xyz)
            with self.assertRaisesRegex(ValueError, r"returned shape \(3,\) for 162 points"):
                s.advect(lambda points, t: np.zeros(3), 0.1)
            np.testing.assert_array_equal(s.mesh()[0], xyz)
            # The surface is still usable.
            self.assertEqual(s.advect(lambda p, t: np.ones_like(p), 0.1), 0.1)


class Fields(unittest.TestCase):
    def test_a_vertex_field_is_carried_through_adapt(self):
        xyz, tris = sphere(3)
        with surfadapt.Surface(xyz, tris) as s:
            linear = s.add_field(xyz @ [1.0, 2.0, -1.0])
            pair = s.add_field(np.column_stack([xyz[:, 0], np.full(len(xyz), 7.0)]))
            self.assertEqual((linear, pair), (0, 1))
            s.set_param("edge_length", 0.04)
            s.adapt()
            new = s.mesh()[0]
            values = s.get_field(linear)
            self.assertEqual(values.shape, (len(new),))
            # Interpolated on the old triangles, so a linear function is off only by the
            # sphere's curvature between the chords and the surface.
            self.assertLess(np.max(np.abs(values - new @ [1.0, 2.0, -1.0])), 0.01)
            both = s.get_field(pair)
            self.assertEqual(both.shape, (len(new), 2))
            np.testing.assert_allclose(both[:, 1], 7.0, rtol=1e-14)
            s.set_field(pair, np.column_stack([both[:, 0], np.full(len(new), -3.0)]))
            np.testing.assert_array_equal(s.get_field(pair)[:, 1], -3.0)
            with self.assertRaises(ValueError):
                s.set_field(pair, np.zeros(len(new)))  # one column, the field has two
            with self.assertRaisesRegex(surfadapt.ArgumentError, "no vertex field 5"):
                s.get_field(5)
            with self.assertRaises(surfadapt.ArgumentError):
                s.add_field(np.zeros(len(xyz)))  # made for the mesh before adapt
            with self.assertRaises(surfadapt.NumericError) as caught:
                bad = np.zeros(len(new))
                bad[9] = np.nan
                s.add_field(bad)
            self.assertIn("9", str(caught.exception))
            s.set_mesh(xyz, tris)  # fields are dropped with the mesh
            with self.assertRaises(surfadapt.ArgumentError):
                s.get_field(linear)

    def test_a_face_field_keeps_its_integral_through_adapt(self):
        xyz, tris = sphere(3)
        with surfadapt.Surface(xyz, tris) as s:
            density = 1.0 + xyz[tris].mean(axis=1)[:, 2] ** 2
            fid = s.add_face_field(density)
            before = np.sum(density * triangle_areas(xyz, tris))
            s.set_param("edge_length", 0.04)
            s.adapt()
            new_xyz, new_tris = s.mesh()
            after_density = s.get_face_field(fid)
            self.assertEqual(after_density.shape, (len(new_tris),))
            after = np.sum(after_density * triangle_areas(new_xyz, new_tris))
            self.assertLess(abs(after - before) / before, 1e-12)
            # The host replaces the densities; the next adapt keeps the new integral.
            s.set_face_field(fid, 2 * after_density)
            s.set_param("edge_length", 0.08)
            s.adapt()
            last_xyz, last_tris = s.mesh()
            last = np.sum(s.get_face_field(fid) * triangle_areas(last_xyz, last_tris))
            self.assertLess(abs(last - 2 * after) / after, 1e-12)
            with self.assertRaises(ValueError):
                s.set_face_field(fid, np.ones((len(last_tris), 2)))
            with self.assertRaises(surfadapt.ArgumentError):
                s.set_face_field(fid, np.ones(len(new_tris)))  # made for the mesh before adapt

    def test_size_field(self):
        xyz, tris = sphere(3)
        with surfadapt.Surface(xyz, tris) as s:
            s.set_size_field(np.where(xyz[:, 2] > 0, 0.03, 0.1))
            s.adapt()
            new = s.mesh()[0]
            self.assertGreater(np.sum(new[:, 2] > 0), 2 * np.sum(new[:, 2] < 0))
            s.set_size_field(None)
            with self.assertRaises(surfadapt.ArgumentError):
                s.set_size_field(np.full(len(new), -1.0))


class Programs(unittest.TestCase):
    """The example, and the module as a user loads it (tests/readme runs the README's program)."""

    def run_python(self, args, cwd=None, **env):
        env = dict(os.environ, OMP_WAIT_POLICY=os.environ.get("OMP_WAIT_POLICY", "passive"), **env)
        return subprocess.run([sys.executable] + args, capture_output=True, text=True, env=env, timeout=120,
                              cwd=cwd)

    def test_volume_history_example(self):
        with tempfile.TemporaryDirectory() as tmp:
            png = os.path.join(tmp, "history.png")
            r = self.run_python([os.path.join(ROOT, "bindings", "python", "examples", "volume_history.py"),
                                 "--steps", "40", "--png", png])
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertRegex(r.stdout, r"(?m)^\s+40\s+2\.000\s+\d+\s")
            worst = float(re.search(r"largest relative volume change: (\S+)", r.stdout).group(1))
            self.assertLess(worst, 0.01)
            if importlib.util.find_spec("matplotlib") is not None:
                self.assertTrue(os.path.isfile(png) and os.path.getsize(png) > 0,
                                "matplotlib is there, but no plot was written")
            else:
                self.assertIn("skipped the plot", r.stdout)

    def test_a_surface_left_open_at_exit_is_freed_quietly(self):
        r = self.run_python(["-c", "import surfadapt; s = surfadapt.Surface(*surfadapt.icosphere(1))"],
                            PYTHONPATH=os.path.join(ROOT, "bindings", "python"))
        self.assertEqual((r.returncode, r.stderr), (0, ""))

    def test_a_wrong_library_path_is_named(self):
        r = self.run_python(["-c", "import surfadapt; surfadapt.Surface()"],
                            PYTHONPATH=os.path.join(ROOT, "bindings", "python"),
                            SURFADAPT_LIBRARY="/nonexistent/libsurfadapt.so.1")
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("/nonexistent/libsurfadapt.so.1", r.stderr)
        self.assertIn("SURFADAPT_LIBRARY", r.stderr)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    failed = len(result.failures) + len(result.errors) + len(result.unexpectedSuccesses)
    passed = result.testsRun - failed - len(result.skipped)
    print(f"python-binding: {passed} passed, {failed} failed")
    sys.exit(0 if failed == 0 and result.testsRun > 0 else 1)
