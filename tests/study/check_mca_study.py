"""Check an automata study (set Problem = mca_study) against its scenes'
own series: tests/study/mca_tiny_study.prm (2 bases x 2 roughness seeds).

    check_mca_study.py TEST_DIR

The study's numbers are recomputed here from what each scene wrote, never
from the study's tables:
1. the scenes are the bases x seeds, each run with the seeds the study set
   (its parameters.prm: Geometry/Rough interface/Seed, Geometry/Inclusions/
   Seed) and named in its summary.json ("study_scene"); the composite scenes
   hold carbon (inclusion_volume_fraction > 0), the steel ones none; the two
   roughness seeds give different scenes (mu_steady differs);
2. each scene's mu_steady is the mean of |F_t| / |F_n| of its friction.csv
   over t >= steady_start_time (an exact identity of the analysis; the CSV
   has 10 significant digits, so agreement to 1e-8 relative);
3. study.csv: per seed, mu of both bases equal those means (1e-8), the
   relative difference mu_c / mu_s - 1 from them (1e-8 absolute) and its
   standard error propagated from the two scenes' mu_steady_stderr
   (summary.json; 1e-8 relative); the mean row: the mean of the per-seed
   differences and the standard error of that mean from their scatter,
   sqrt(sum (d_i - d)^2 / (n - 1) / n) (1e-8 relative), n_seeds = 2;
4. the difference paired in time, recomputed from the two friction.csv:
   both mu(t) binned onto bins of twice the larger mean sample spacing from
   the later steady_start_time to the earlier end, d_k = mu_c,k - mu_s,k
   over the bins both fill, relative to the mean of mu_s,k: the mean to
   1e-9 (same inputs, same sums); its standard error must be one of the
   blocking levels' estimates sqrt(sum (x - m)^2 / (n (n - 1))) of the
   halved series of d_k (block averaging picks a level: an identity of the
   method, 1e-9), divided by the reference mean; the mean row: the mean of
   the two and the standard error from their scatter (1e-8).
"""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, parameter, report  # noqa: E402

study = os.path.join(sys.argv[1], "output-mca-tiny-study")
SEEDS = {1: 5, 2: 6}          # roughness seed -> inclusion seed
BASES = ("steel", "composite")


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def recomputed_mu(directory, start):
    """Mean of |F_t| / |F_n| over t >= start, from friction.csv."""
    values = []
    for row in read_rows(os.path.join(directory, "friction.csv")):
        # times carry 10 significant digits: the start sample within 1e-9
        if float(row["time"]) >= start * (1 - 1e-9):
            fn = abs(float(row["normal_force"]))
            values.append(abs(float(row["tangential_force"])) / fn
                          if fn > 0 else 0.0)
    return sum(values) / len(values), len(values)


def mu_series(directory):
    rows = read_rows(os.path.join(directory, "friction.csv"))
    return [float(r["time"]) for r in rows], [float(r["mu"]) for r in rows]


def in_time(dir_s, dir_c, start):
    """(relative difference paired in time, [blocking estimates / ref])."""
    (ts, ms), (tc, mc) = mu_series(dir_s), mu_series(dir_c)
    w = 2 * max((ts[-1] - ts[0]) / (len(ts) - 1),
                (tc[-1] - tc[0]) / (len(tc) - 1))
    n = int((min(ts[-1], tc[-1]) - start) / w)

    def bins(t, m):
        total, count = [0.0] * n, [0] * n
        for tk, mk in zip(t, m):
            x = (tk - start) / w
            if 0 <= x < n:
                total[int(x)] += mk
                count[int(x)] += 1
        return [a / c if c else None for a, c in zip(total, count)]
    bs, bc = bins(ts, ms), bins(tc, mc)
    d = [c - s for s, c in zip(bs, bc) if s is not None and c is not None]
    ref = sum(s for s, c in zip(bs, bc) if s is not None and c is not None)
    ref /= len(d)
    estimates, x = [], d
    while len(x) >= 2:
        m = sum(x) / len(x)
        estimates.append(math.sqrt(sum((v - m) ** 2 for v in x)
                                   / len(x) / (len(x) - 1)) / abs(ref))
        x = [0.5 * (x[2 * i] + x[2 * i + 1]) for i in range(len(x) // 2)]
    return sum(d) / len(d) / ref, estimates, len(d)


def close(a, b, tol):
    return abs(a - b) <= tol * max(abs(b), 1e-300)


mu, se, start, dirs = {}, {}, {}, {}
for seed, inclusion_seed in SEEDS.items():
    for base in BASES:
        name = "%s_seed%d_inclusions%d" % (base, seed, inclusion_seed)
        directory = os.path.join(study, "scenes", name)
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)
        tag = summary.get("study_scene", {})
        report(tag.get("base") == base and tag.get("roughness_seed") == seed
               and tag.get("inclusion_seed") == inclusion_seed,
               "%s: summary.json names base, roughness and inclusion seed: %s"
               % (name, tag))
        report(parameter(directory, "Geometry/Rough interface/Seed") == seed
               and parameter(directory, "Geometry/Inclusions/Seed")
               == inclusion_seed,
               "%s: run with roughness seed %d, inclusion seed %d"
               % (name, seed, inclusion_seed))
        fraction = summary["inclusion_volume_fraction"]
        report((fraction > 0) == (base == "composite"),
               "%s: inclusion volume fraction %.4f" % (name, fraction))
        m, n = recomputed_mu(directory, summary["steady_start_time"])
        report(n >= 8 and close(summary["mu_steady"], m, 1e-8),
               "%s: mu_steady %.10g = mean of |F_t|/|F_n| over %d samples "
               "from t = %.4g s (%.10g)" % (name, summary["mu_steady"], n,
                                            summary["steady_start_time"], m))
        mu[(base, seed)] = m
        se[(base, seed)] = summary["mu_steady_stderr"]
        start[(base, seed)] = summary["steady_start_time"]
        dirs[(base, seed)] = directory
report(mu[("steel", 1)] != mu[("steel", 2)],
       "the roughness seeds give different steel scenes (mu %.4f, %.4f)"
       % (mu[("steel", 1)], mu[("steel", 2)]))

rows = read_rows(os.path.join(study, "study.csv"))
seed_rows = {int(r["roughness_seed"]): r for r in rows if r["row"] == "seed"}
mean_rows = [r for r in rows if r["row"] == "mean"]
report(sorted(seed_rows) == [1, 2] and len(mean_rows) == 1
       and all(r["compare"] == "composite" and r["reference"] == "steel"
               for r in rows),
       "study.csv: a row per seed and one mean, composite against steel")
differences = []
for seed in (1, 2):
    r = seed_rows[seed]
    ms, mc = mu[("steel", seed)], mu[("composite", seed)]
    d = mc / ms - 1
    sd = abs(mc / ms) * math.hypot(se[("composite", seed)] / mc,
                                   se[("steel", seed)] / ms)
    differences.append(d)
    report(close(float(r["mu_reference"]), ms, 1e-8)
           and close(float(r["mu_compare"]), mc, 1e-8),
           "seed %d: mu steel %.6f, composite %.6f as recomputed"
           % (seed, ms, mc))
    report(abs(float(r["relative_difference"]) - d) <= 1e-8,
           "seed %d: relative difference %+.6f (recomputed %+.6f)"
           % (seed, float(r["relative_difference"]), d))
    report(close(float(r["relative_difference_stderr"]), sd, 1e-8),
           "seed %d: its standard error %.6g (propagated here %.6g)"
           % (seed, float(r["relative_difference_stderr"]), sd))
in_time_values = []
for seed in (1, 2):
    r = seed_rows[seed]
    value, estimates, n_bins = in_time(
        dirs[("steel", seed)], dirs[("composite", seed)],
        max(start[("steel", seed)], start[("composite", seed)]))
    in_time_values.append(value)
    stderr = float(r["relative_difference_in_time_stderr"])
    report(abs(float(r["relative_difference_in_time"]) - value) <= 1e-9
           and int(r["in_time_bins"]) == n_bins,
           "seed %d: difference paired in time %+.6f over %d bins "
           "(recomputed %+.6f over %d)"
           % (seed, float(r["relative_difference_in_time"]),
              int(r["in_time_bins"]), value, n_bins))
    report(any(close(stderr, e, 1e-9) for e in estimates),
           "seed %d: its standard error %.6g is a blocking level's estimate "
           "(levels: %s)" % (seed, stderr,
                             ", ".join("%.3g" % e for e in estimates[:8])))
m_in_time = sum(in_time_values) / 2
r = mean_rows[0]
report(abs(float(r["relative_difference_in_time"]) - m_in_time) <= 1e-9
       and close(float(r["relative_difference_in_time_stderr"]),
                 abs(in_time_values[0] - in_time_values[1]) / 2, 1e-8),
       "mean paired in time %+.6f ± %.4g (recomputed %+.6f ± %.4g)"
       % (float(r["relative_difference_in_time"]),
          float(r["relative_difference_in_time_stderr"]), m_in_time,
          abs(in_time_values[0] - in_time_values[1]) / 2))
mean = sum(differences) / 2
sem = math.sqrt(sum((x - mean) ** 2 for x in differences) / 1 / 2)
r = mean_rows[0]
report(abs(float(r["relative_difference"]) - mean) <= 1e-8
       and int(r["n_seeds"]) == 2,
       "mean over the seeds %+.6f (recomputed %+.6f), n_seeds %s"
       % (float(r["relative_difference"]), mean, r["n_seeds"]))
report(close(float(r["relative_difference_stderr"]), sem, 1e-8),
       "its standard error from the scatter %.6g (recomputed %.6g)"
       % (float(r["relative_difference_stderr"]), sem))
with open(os.path.join(study, "summary.json")) as f:
    summary = json.load(f)
report(summary.get("n_scenes") == 4 and summary.get("n_scenes_finished") == 4
       and summary.get("core_hours", 0) > 0,
       "summary.json: 4 scenes finished, core-hours %.2g"
       % summary.get("core_hours", 0))
finish()
