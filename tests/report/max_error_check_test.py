"""Unit tests of the quality report's --max-error checks (bench/quality_report/max_error.py): CGAL's
H nRMS at a vertex count, the ratio and the verdict; and of the ideal-lattice yardstick set beside the
H checks (max_error.ideal_ratio, targets.h_versus_cgal). Run by ctest (tests/report/CMakeLists.txt)."""

import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench", "quality_report"))

import max_error  # noqa: E402
import targets  # noqa: E402
from metrics import metrics  # noqa: E402
from runs import Run  # noqa: E402
from surfaces import SurfaceSpec  # noqa: E402


def analysed(system, vertices, h_nrms, value=1.0, centroid=0.5, valence6=0.95, min_angle=25.0, crossings=0):
    """A run with the parts of `isopatch analyze --json` that the checks read."""
    analysis = {
        "valence": {"share_6": valence6},
        "shape": {"min_angle_degrees": {"min": min_angle}, "share_below_10_degrees": 0.0},
        "accuracy": {"mean_curvature": {"nrms": h_nrms}, "vertex_distance_relative": {"max": 1e-14},
                     "centroid_distance": {"max": centroid * value}},
        "topology": {"watertight": True, "manifold": True, "consistently_oriented": True,
                     "outward_oriented": True, "genus": 1, "components": 1},
        "self_intersections": {"pairs": crossings},
    }
    return Run(system, f"knob {value}", value, ok=True, vertices=vertices, analysis=analysis)


CGAL = [analysed("cgal", 2000, 0.08), analysed("cgal", 10000, 0.05), analysed("cgal", 40000, 0.04)]
TORUS = SurfaceSpec("torus", "closed", 1)


class CgalAtCount(unittest.TestCase):
    def test_at_a_measured_count_gives_that_run(self):
        self.assertAlmostEqual(max_error.cgal_h_nrms_at(CGAL, 10000), 0.05)

    def test_between_two_runs_is_log_log_linear(self):
        v = math.sqrt(2000 * 10000)  # halfway in log(count)
        self.assertAlmostEqual(max_error.cgal_h_nrms_at(CGAL, round(v)), math.sqrt(0.08 * 0.05), places=4)

    def test_outside_the_runs_takes_the_nearest(self):
        self.assertAlmostEqual(max_error.cgal_h_nrms_at(CGAL, 500), 0.08)
        self.assertAlmostEqual(max_error.cgal_h_nrms_at(CGAL, 90000), 0.04)

    def test_order_of_the_runs_does_not_matter(self):
        self.assertAlmostEqual(max_error.cgal_h_nrms_at(CGAL[::-1], 5000), max_error.cgal_h_nrms_at(CGAL, 5000))

    def test_failed_or_unanalysed_runs_are_ignored(self):
        failed = Run("cgal", "R 1", 1.0, ok=False, error="timeout")
        unanalysed = Run("cgal", "R 1", 1.0, ok=True, vertices=5000)
        self.assertIsNone(max_error.cgal_h_nrms_at([failed, unanalysed], 5000))
        self.assertAlmostEqual(max_error.cgal_h_nrms_at([failed, CGAL[1]], 3000), 0.05)


class Verdict(unittest.TestCase):
    def test_a_fifth_of_cgal_is_met(self):
        run = analysed("max-error", 10000, 0.0099)
        self.assertAlmostEqual(max_error.h_ratio(run, CGAL), 0.198)
        self.assertEqual(max_error.check(TORUS, run, CGAL), ("met", ""))

    def test_above_a_fifth_of_cgal_is_not_met(self):
        status, why = max_error.check(TORUS, analysed("max-error", 10000, 0.0101), CGAL)
        self.assertEqual(status, "**not met**")
        self.assertIn("CGAL", why)

    def test_without_cgal_the_ratio_is_not_checked(self):
        self.assertEqual(max_error.check(TORUS, analysed("max-error", 10000, 0.03), []), ("met", ""))

    def test_a_cgal_run_without_h_fails_the_check(self):
        status, why = max_error.check(TORUS, analysed("max-error", 10000, None), CGAL)
        self.assertEqual(status, "**not met**")
        self.assertIn("no H nRMS", why)

    def test_a_self_intersecting_mesh_is_not_met(self):
        status, why = max_error.check(TORUS, analysed("max-error", 10000, 0.001, crossings=3), CGAL)
        self.assertEqual(status, "**not met**")
        self.assertIn("topology", why)

    def test_the_bound_is_still_checked(self):
        status, why = max_error.check(TORUS, analysed("max-error", 10000, 0.001, centroid=1.2), CGAL)
        self.assertEqual(status, "**not met**")
        self.assertIn("EPS", why)


class IdealLattice(unittest.TestCase):
    def test_ratio_to_cgal_at_the_runs_count(self):
        run = analysed("max-error", 10000, 0.02)
        run.ideal = {"nrms_mean": 0.025, "nrms_best": 0.02}
        self.assertAlmostEqual(max_error.ideal_ratio(run, CGAL), 0.5)

    def test_missing_yardstick_or_cgal_gives_none(self):
        run = analysed("max-error", 10000, 0.02)
        self.assertIsNone(max_error.ideal_ratio(run, CGAL))
        run.ideal = {"nrms_mean": 0.025}
        self.assertIsNone(max_error.ideal_ratio(run, []))

    def test_the_yardstick_does_not_change_the_verdict(self):
        run = analysed("max-error", 10000, 0.0099)
        run.ideal = {"nrms_mean": 1.0}
        self.assertEqual(max_error.check(TORUS, run, CGAL), ("met", ""))

    def test_edge_length_check_shows_both_ratios(self):
        p, c = analysed("projection", 2000, 0.04), CGAL[0]
        p.ideal = {"nrms_mean": 0.12}
        v = targets.h_versus_cgal(p, metrics(p.analysis), c, metrics(c.analysis))
        self.assertAlmostEqual(v[0], 0.5)
        self.assertAlmostEqual(v[1], 1.5)
        self.assertEqual(targets.describe_h_ratio(v), "0.500× CGAL's (ideal lattice 1.50×)")
        p.ideal = None
        v = targets.h_versus_cgal(p, metrics(p.analysis), c, metrics(c.analysis))
        self.assertEqual(targets.describe_h_ratio(v), "0.500× CGAL's")


if __name__ == "__main__":
    unittest.main()
