"""The default pin's short run through the executable (app_pin.prm, on 1-4
ranks): its outputs, its time step against the element eigenproblem the
test solves, and its vertical momentum against the load it was given.

1. Outputs: summary.json has every documented key; the CSV files have their
   header and rows; the VTU fields and their .pvd index exist.
2. Mesh: n_dofs = 2 (W/h + 1)(H/h + 1) from Geometry/Width, Height and
   Mesh size (7458 for 112 x 32 Q1 cells); exact.
3. Stability bound (doc/theory/contact.md section 2): the test assembles the
   plane-strain Q1 element of side h (2 x 2 Gauss points) and its lumped
   mass rho h^2 / 4 itself, finds the largest eigenvalue of M^-1 K by
   power iteration, and forms dt_crit = (sqrt(2 b2 + xi^2) - xi) / (b2
   omega) with xi = beta omega / 2. omega_max and critical_dt must agree
   to 1e-12 (measured 4.4e-16: the same eigenvalue by another method, so
   round-off of the two solvers on entries of 1e11); the
   automatic dt is Safety factor x dt_crit (1e-12). An error of 1 % in E,
   rho or h moves omega by 0.5 % or more.
4. Vertical momentum (the pin's top is held in x only, so y is free): with
   the lumped mass and stiffness-proportional damping (whose forces sum to
   zero: a rigid translation strains nothing), the beta2 scheme gives
   exactly p_y(t_k) - p_y(t_k-1) = dt [(1 - b2) F_k-1 + b2 F_k] with
   F = N - P(t) W, N the contact normal force (friction.csv) and P(t) the
   pressure ramp P (1 - cos(pi t / t_r)) / 2 of Loading/Pressure, Ramp time
   and Geometry/Width (computed here, not read from the code's
   normal_force column). Summed over the 397 steps, the balance must hold
   to 5e-10 of the load's impulse (measured 7.8e-11: the CSV's ten
   significant digits). Shown failing with the width 0.1 % off in this
   script (1.0e-3), and the bound with rho 1 % off (omega 5e-3)."""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import plot_tools  # noqa: E402  (read_parameters)

out = os.path.join(sys.argv[1], "output")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
prm = plot_tools.read_parameters(out)
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def number(path):
    return float(prm[path])


for key in ["mu_global_mean", "dominant_frequency_hz", "energy_balance_error",
            "stick_fraction", "slip_fraction", "separation_fraction", "n_dofs",
            "n_steps", "dt", "critical_dt", "wall_time_s", "dof_steps_per_second",
            "tribodyn_version", "n_mpi_ranks", "regime", "point_M"]:
    check(key in s, "summary.json has key " + key)
check(abs(s["stick_fraction"] + s["slip_fraction"] + s["separation_fraction"] - 1)
      < 1e-12, "status fractions sum to 1")
for name, column in [("friction.csv", "mu_global"), ("point_M.csv", "status"),
                     ("contact_status.csv", "slip_fraction"),
                     ("spectrum.csv", "amplitude")]:
    with open(os.path.join(out, name)) as f:
        rows = list(csv.DictReader(f))
    check(len(rows) > 2 and column in rows[0], name + " has rows and column " + column)
for name in ["fields.pvd", "fields_00000.vtu", "fields_00001.vtu", "parameters.prm"]:
    check(os.path.exists(os.path.join(out, name)), name + " exists")

# 2. The mesh.
h = number("Geometry/Mesh size")
width, height = number("Geometry/Width"), number("Geometry/Height")
nx, ny = round(width / h), round(height / h)
check(s["n_dofs"] == 2 * (nx + 1) * (ny + 1),
      "n_dofs %d = 2 (%d + 1)(%d + 1)" % (s["n_dofs"], nx, ny))

# 3. The element eigenproblem.
E = number("Materials/Matrix/Young modulus")
nu = number("Materials/Matrix/Poisson ratio")
rho = number("Materials/Matrix/Density")
c = E / ((1 + nu) * (1 - 2 * nu))
D = [[c * (1 - nu), c * nu, 0], [c * nu, c * (1 - nu), 0], [0, 0, c * (1 - 2 * nu) / 2]]
K = [[0.0] * 8 for _ in range(8)]
corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
g = 1 / math.sqrt(3)
for qx, qy in [(-g, -g), (g, -g), (g, g), (-g, g)]:
    # dN/dx on the square [0, h]^2 (Jacobian h/2, weight 1 per point)
    dN = [(cx * (1 + cy * qy) / (2 * h), cy * (1 + cx * qx) / (2 * h)) for cx, cy in corners]
    B = [[0.0] * 8 for _ in range(3)]
    for a, (dx, dy) in enumerate(dN):
        B[0][2 * a], B[1][2 * a + 1] = dx, dy
        B[2][2 * a], B[2][2 * a + 1] = dy, dx
    for i in range(8):
        for j in range(8):
            K[i][j] += sum(B[p][i] * D[p][q] * B[q][j]
                           for p in range(3) for q in range(3)) * (h / 2) ** 2
mass = rho * h * h / 4
v = [1.0 + 0.1 * i * (-1) ** i for i in range(8)]
lam = 0
for _ in range(20000):
    w = [sum(K[i][j] * v[j] for j in range(8)) / mass for i in range(8)]
    norm = math.sqrt(sum(x * x for x in w))
    lam, v = norm / math.sqrt(sum(x * x for x in v)), [x / norm for x in w]
omega = math.sqrt(lam)
beta2 = number("Time/Beta2")
xi = number("Time/Damping coefficient") * omega / 2
dt_crit = (math.sqrt(2 * beta2 + xi * xi) - xi) / (beta2 * omega)
check(abs(s["omega_max"] - omega) <= 1e-12 * omega,
      "omega_max %.10g = %.10g from the element eigenproblem (difference %.2g)"
      % (s["omega_max"], omega, abs(s["omega_max"] / omega - 1)))
check(abs(s["critical_dt"] - dt_crit) <= 1e-12 * dt_crit,
      "critical_dt %.10g = %.10g (difference %.2g)"
      % (s["critical_dt"], dt_crit, abs(s["critical_dt"] / dt_crit - 1)))
safety = number("Time/Safety factor")
check(abs(s["dt"] - safety * dt_crit) <= 1e-12 * s["dt"],
      "automatic dt %g = %g x dt_crit (Time step %g is above it)"
      % (s["dt"], safety, number("Time/Time step")))

# 4. The vertical momentum.
pressure, ramp = number("Loading/Pressure"), number("Loading/Ramp time")


def load(t):
    return pressure * width * ((1 - math.cos(math.pi * t / ramp)) / 2 if t < ramp else 1)


with open(os.path.join(out, "friction.csv")) as f:
    rows = [{k: float(x) for k, x in r.items()} for r in csv.DictReader(f)]
check(len(rows) > 300 and all(abs(r["time"] - q["time"] - s["dt"]) <= 1e-6 * s["dt"]
                              for q, r in zip(rows, rows[1:])),
      "friction.csv has every step (%d rows, one dt apart)" % len(rows))
impulse, scale, worst = 0.0, 0.0, 0.0
for prev, row in zip(rows, rows[1:]):
    dt = row["time"] - prev["time"]
    f0 = prev["contact_normal_force"] - load(prev["time"])
    f1 = row["contact_normal_force"] - load(row["time"])
    impulse += dt * ((1 - beta2) * f0 + beta2 * f1)
    scale += dt * load(row["time"])
    worst = max(worst, abs(row["momentum_y"] - rows[0]["momentum_y"] - impulse))
check(worst <= 5e-10 * scale,
      "vertical momentum = impulse of the pressure and the contact forces: "
      "largest difference %.3g of the load's impulse %.4g N s (<= 5e-10)"
      % (worst / scale, scale))
sys.exit(1 if failures else 0)
