"""Small helpers of the homogenization tests: linear algebra of small
matrices in plain Python (no numpy on the test machines; the 2D checks
take inverse() too), and for the 3D tests (issue #51) the isotropic
stiffness and its isotropic projection, the exact laminate, raw volumes and
runs of tribodyn.

Voigt order (xx, yy, zz, yz, xz, xy), engineering shears, as tribodyn's
summary.json writes C and S.
"""
import json
import math
import os
import subprocess


def inverse(A):
    """Gauss-Jordan with partial pivoting."""
    n = len(A)
    a = [list(map(float, row)) + [1.0 if i == j else 0.0 for j in range(n)]
         for i, row in enumerate(A)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        d = a[c][c]
        a[c] = [x / d for x in a[c]]
        for r in range(n):
            if r != c and a[r][c] != 0.0:
                f = a[r][c]
                a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return [row[n:] for row in a]


def mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(len(B)))
             for j in range(len(B[0]))] for i in range(len(A))]


def sub(A, B):
    return [[a - b for a, b in zip(ra, rb)] for ra, rb in zip(A, B)]


def norm(A):
    return math.sqrt(sum(x * x for row in A for x in row))


def min_eigenvalue(A):
    """Smallest eigenvalue of the symmetric part of A (cyclic Jacobi)."""
    n = len(A)
    a = [[0.5 * (A[i][j] + A[j][i]) for j in range(n)] for i in range(n)]
    for _ in range(100):
        off = sum(a[i][j] ** 2 for i in range(n) for j in range(i + 1, n))
        if off <= 1e-30 * sum(a[i][i] ** 2 for i in range(n)):
            break
        for p in range(n):
            for q in range(p + 1, n):
                if a[p][q] == 0.0:
                    continue
                theta = (a[q][q] - a[p][p]) / (2 * a[p][q])
                t = math.copysign(1.0, theta) / (abs(theta)
                                                 + math.sqrt(theta ** 2 + 1))
                c = 1 / math.sqrt(t * t + 1)
                s = t * c
                for k in range(n):
                    akp, akq = a[k][p], a[k][q]
                    a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(n):
                    apk, aqk = a[p][k], a[q][k]
                    a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
    return min(a[i][i] for i in range(n))


def isotropic_stiffness(E, nu):
    """Hooke's law: lambda + 2 mu, lambda in the normal block, mu on the
    engineering shears."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    C = [[0.0] * 6 for _ in range(6)]
    for i in range(3):
        for j in range(3):
            C[i][j] = lam + (2 * mu if i == j else 0.0)
        C[3 + i][3 + i] = mu
    return C


def isotropic_projection(C):
    """(k, mu) of a 6 x 6 stiffness, exact for an isotropic one:
    k = (C11 + C22 + C33 + 2 (C12 + C13 + C23)) / 9,
    mu = (C11 + C22 + C33 - C12 - C13 - C23 + 3 (C44 + C55 + C66)) / 15."""
    k = (C[0][0] + C[1][1] + C[2][2] + 2 * (C[0][1] + C[0][2] + C[1][2])) / 9
    mu = (C[0][0] + C[1][1] + C[2][2] - C[0][1] - C[0][2] - C[1][2]
          + 3 * (C[3][3] + C[4][4] + C[5][5])) / 15
    return k, mu


def anisotropy(C):
    """|C - C_iso| / |C| with C_iso the isotropic stiffness of the
    projection (k, mu): lambda + 2 mu and lambda = k - 2 mu / 3 in the
    normal block, mu on the engineering shears."""
    k, mu = isotropic_projection(C)
    lam = k - 2 * mu / 3
    iso = [[0.0] * 6 for _ in range(6)]
    for i in range(3):
        for j in range(3):
            iso[i][j] = lam + (2 * mu if i == j else 0.0)
        iso[3 + i][3 + i] = mu
    return norm(sub(C, iso)) / norm(C)


def laminate_exact(stiffnesses, fractions, normal):
    """Exact effective stiffness of layers normal to axis `normal` (0, 1, 2).

    Across the layers the traction sigma.n is continuous, along them the
    strain is compatible: the components n = (sigma_aa, sigma_ab, sigma_ac)
    of the traction are uniform, the in-layer strains t = (eps_bb, eps_cc,
    gamma_bc) are uniform, the other components are constant in each layer.
    With the blocks C_nn, C_nt, C_tn, C_tt of each phase's stiffness,
        eps_n^k = C_nn^k^-1 (sigma_n - C_nt^k eps_t),
        <eps_n> = <C_nn^-1> sigma_n - <C_nn^-1 C_nt> eps_t
    gives sigma_n from the macroscopic strain, then
        <sigma_t> = <C_tt - C_tn C_nn^-1 C_nt> eps_t + <C_tn C_nn^-1> sigma_n.
    """
    a = normal
    b, c = (a + 1) % 3, (a + 2) % 3
    n_idx = [a, 3 + c, 3 + b]   # sigma_aa, and the shears of planes with a
    t_idx = [b, c, 3 + a]       # eps_bb, eps_cc, gamma_bc

    def block(C, rows, cols):
        return [[C[i][j] for j in cols] for i in rows]

    def avg(mats):
        return [[sum(f * M[i][j] for f, M in zip(fractions, mats))
                 for j in range(len(mats[0][0]))]
                for i in range(len(mats[0]))]

    inv_nn = [inverse(block(C, n_idx, n_idx)) for C in stiffnesses]
    A = avg(inv_nn)
    B = avg([mul(inv_nn[k], block(C, n_idx, t_idx))
             for k, C in enumerate(stiffnesses)])
    D = avg([mul(block(C, t_idx, n_idx), inv_nn[k])
             for k, C in enumerate(stiffnesses)])
    T = avg([sub(block(C, t_idx, t_idx),
                 mul(mul(block(C, t_idx, n_idx), inv_nn[k]),
                     block(C, n_idx, t_idx)))
             for k, C in enumerate(stiffnesses)])
    A_inv = inverse(A)
    C_eff = [[0.0] * 6 for _ in range(6)]
    for col in range(6):
        eps = [1.0 if i == col else 0.0 for i in range(6)]
        e_t = [[eps[i]] for i in t_idx]
        e_n = [[eps[i]] for i in n_idx]
        Be = mul(B, e_t)
        s_n = mul(A_inv, [[e_n[i][0] + Be[i][0]] for i in range(3)])
        s_t = [[x[0] + y[0]] for x, y in zip(mul(T, e_t), mul(D, s_n))]
        for i, row in zip(n_idx, s_n):
            C_eff[i][col] = row[0]
        for i, row in zip(t_idx, s_t):
            C_eff[i][col] = row[0]
    return C_eff


# The two phases the glass/epoxy volume tests use (matrix id 0, glass id 1).
GLASS_EPOXY_MATERIALS = """subsection Materials
  subsection Matrix
    set Young modulus = 3e9
    set Poisson ratio = 0.35
  end
  subsection Heterogeneity
    set Young modulus = 70e9
    set Poisson ratio = 0.22
  end
end
"""


def write_raw(directory, name, ids, n, h):
    """Write ids (a dict or function (i, j, k) -> id, x fastest) as
    NAME.raw with its header NAME.hdr (voxel size h, or (hx, hy, hz));
    returns the header's path."""
    nx, ny, nz = n
    if isinstance(h, (tuple, list)):  # hx hy hz
        h = " ".join(repr(x) for x in h)
    data = bytes(ids(i, j, k) for k in range(nz) for j in range(ny)
                 for i in range(nx))
    with open(os.path.join(directory, name + ".raw"), "wb") as f:
        f.write(data)
    header = os.path.join(directory, name + ".hdr")
    with open(header, "w") as f:
        f.write("# written by tests/homogenization/volume_tools.py\n"
                "size = %d %d %d\nvoxel size = %s\ntype = uint8\n"
                "file = %s.raw\n" % (nx, ny, nz, h, name))
    return header


def raw_volume_prm(header):
    """The first lines of a test's parameter file: the 3D problem on the
    raw volume of `header`, its outputs in output/ of the run's directory;
    the test appends its materials and cell problem."""
    return ("set Problem = volume_homogenization\n"
            "set Output directory = output\n"
            "subsection Morphology\n"
            "  set Generator  = raw file\n"
            "  set Raw header = %s\n"
            "end\n" % header)


def materials_prm(phases):
    """The subsection Materials of the named materials @p phases, a list of
    (name, E, nu, rho): material id k is the k-th."""
    text = "subsection Materials\n  set Names = %s\n" % ", ".join(p[0] for p in phases)
    for name, E, nu, rho in phases:
        text += ("  subsection %s\n    set Young modulus = %r\n    set Poisson ratio = %r\n"
                 "    set Density       = %r\n  end\n" % (name[0].upper() + name[1:], E, nu, rho))
    return text + "end\n"


def given_materials(prm):
    """(E, nu) of each material of 'Materials/Names' in a run's parameters
    (plot_tools.read_parameters)."""
    names = [n.strip() for n in prm["Materials/Names"].split(",")]
    return [(float(prm["Materials/%s/Young modulus" % (n[0].upper() + n[1:])]),
             float(prm["Materials/%s/Poisson ratio" % (n[0].upper() + n[1:])]))
            for n in names]


def run(tribodyn, directory, prm_text, ranks=1):
    """Run tribodyn on prm_text in `directory` (fresh output/); returns
    summary.json."""
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    with open(prm, "w") as f:
        f.write(prm_text)
    command = [os.path.abspath(tribodyn), "run.prm"]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    out = subprocess.run(command, cwd=directory, capture_output=True,
                         text=True)
    print(out.stdout)
    if out.returncode != 0:
        print(out.stderr)
        raise SystemExit("tribodyn failed in %s (exit code %d)"
                         % (directory, out.returncode))
    with open(os.path.join(directory, "output", "summary.json")) as f:
        return json.load(f)


def check_laminate(check, s, given, fractions, normal, max_iterations=30):
    """The checks of a laminate's summary.json `s` (layers normal to the
    axis `normal`, phases of (E, nu) `given` at `fractions`) against its
    exact stiffness laminate_exact(), used by check_volume_laminate.py and
    check_volume_image_laminate.py:
    - periodic C and S = the exact ones, |dC|/|C| <= 1e-10: the exact field
      is piecewise affine, in the Q1 space, and periodic (the CG tolerance
      1e-12 allows ~1e-12);
    - Huet: C^KUBC - C_exact and C_exact - C^SUBC positive semi-definite
      (to -1e-9 |C|);
    - the exact load cases of KUBC and SUBC: under the shear in the layers'
      plane the uniform strain is the solution (KUBC: that diagonal entry
      = <mu>, its column diagonal), under the two shears of the planes
      across the layers the uniform stress is (SUBC: S = <1/mu>), 1e-10.
    - fewer than `max_iterations` CG iterations per load case (a guard
      against a preconditioner gone wrong; the bound depends on the
      contrast).
    Voigt order xx, yy, zz, yz, xz, xy: the shear in the plane normal to
    axis a is 3 + a."""
    C_phase = [isotropic_stiffness(E, nu) for E, nu in given]
    exact = laminate_exact(C_phase, fractions, normal)
    scale = norm(exact)
    per = s["periodic"]["C"]
    error = norm(sub(per, exact)) / scale
    check(error <= 1e-10,
          "periodic C = exact laminate C: |dC|/|C| = %.2e <= 1e-10" % error)
    S_exact = inverse(exact)
    error_S = norm(sub(s["periodic"]["S"], S_exact)) / norm(S_exact)
    check(error_S <= 1e-10, "periodic S = exact laminate S: %.2e <= 1e-10"
          % error_S)
    axis = "xyz"[normal]
    E_n = 1 / S_exact[normal][normal]
    check(abs(s["periodic"]["E_" + axis] - E_n) <= 1e-10 * E_n,
          "periodic E_%s = %.6g GPa (exact %.6g)"
          % (axis, s["periodic"]["E_" + axis] / 1e9, E_n / 1e9))

    kubc, subc = s["KUBC"]["C"], s["SUBC"]["C"]
    lower = min_eigenvalue(sub(kubc, exact)) / scale
    upper = min_eigenvalue(sub(exact, subc)) / scale
    check(lower >= -1e-9,
          "C^KUBC - C_exact >= 0 (min eigenvalue / |C| = %.2e)" % lower)
    check(upper >= -1e-9,
          "C_exact - C^SUBC >= 0 (min eigenvalue / |C| = %.2e)" % upper)
    mu = [E / (2 * (1 + nu)) for E, nu in given]
    mu_voigt = sum(f * m for f, m in zip(fractions, mu))
    inv_mu_reuss = sum(f / m for f, m in zip(fractions, mu))
    q = 3 + normal
    check(abs(kubc[q][q] - mu_voigt) <= 1e-10 * mu_voigt,
          "KUBC C_%d%d = <mu> = %.6g GPa (got %.6g)"
          % (q + 1, q + 1, mu_voigt / 1e9, kubc[q][q] / 1e9))
    off = max(abs(kubc[i][q]) for i in range(6) if i != q) / scale
    check(off <= 1e-10, "KUBC column %d diagonal (%.1e)" % (q + 1, off))
    S_subc = s["SUBC"]["S"]
    for i in (3 + (normal + 1) % 3, 3 + (normal + 2) % 3):
        check(abs(S_subc[i][i] - inv_mu_reuss) <= 1e-10 * inv_mu_reuss,
              "SUBC S_%d%d = <1/mu> (relative error %.1e)"
              % (i + 1, i + 1, abs(S_subc[i][i] / inv_mu_reuss - 1)))
    check(s["huet"]["KUBC_minus_SUBC_holds"] is True,
          "summary.json reports Huet's ordering KUBC >= SUBC")
    check(all(0 <= n < max_iterations for bc in ("KUBC", "SUBC", "periodic")
              for n in s[bc]["cg_iterations"]),
          "CG iterations below %d: %s"
          % (max_iterations, {bc: s[bc]["cg_iterations"]
                              for bc in ("KUBC", "SUBC", "periodic")}))


class Checks:
    """PASS/FAIL lines and the exit code."""

    def __init__(self):
        self.failures = []

    def __call__(self, condition, what):
        print(("PASS  " if condition else "FAIL  ") + what)
        if not condition:
            self.failures.append(what)

    def exit(self):
        if self.failures:
            print("%d check(s) failed" % len(self.failures))
        raise SystemExit(1 if self.failures else 0)


def synthetic_images():
    """scripts/make_synthetic_images as a module (the drawings of the
    shipped and test images, and its PNG and TIFF writers)."""
    import importlib.util
    from importlib.machinery import SourceFileLoader
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                          "..", "scripts", "make_synthetic_images")
    loader = SourceFileLoader("make_synthetic_images", script)
    module = importlib.util.module_from_spec(
        importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


def read_pvd(directory, name):
    """The files a .pvd lists, by timestep: [(timestep, file), ...]."""
    import re
    with open(os.path.join(directory, name)) as f:
        text = f.read()
    return [(int(t), f) for t, f in
            re.findall(r'<DataSet timestep="(\d+)"[^>]* file="([^"]+)"', text)]


def read_pvtu_cells(directory, name, h):
    """The cells of the pieces a .pvtu lists (deal.II's VTU: one patch of 8
    points per hexahedron, the cell fields repeated on its points), read
    with scripts/plot_tools.read_vtu: (pieces, cells), cells a dict
    (i, j, k) -> {field: value, "points": [8 points], "displacement":
    [8 vectors]}, (i, j, k) the voxel of the cell's centre for the voxel
    size h."""
    import re
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(
        __file__)), "..", "..", "scripts"))
    import plot_tools
    with open(os.path.join(directory, name)) as f:
        pieces = re.findall(r'<Piece Source="([^"]+)"', f.read())
    cells = {}
    duplicates = 0
    for piece in pieces:
        if not os.path.isfile(os.path.join(directory, piece)):
            continue  # (the caller checks that every piece is there)
        data = plot_tools.read_vtu(os.path.join(directory, piece))
        points = data.pop("points")
        # (not the field data, e.g. TIME: one value per file)
        data = {k: x for k, x in data.items() if len(x) == len(points)}
        for c in range(len(points) // 8):
            p = points[8 * c:8 * c + 8]
            key = tuple(int(sum(q[d] for q in p) / 8 / h[d]) for d in range(3))
            duplicates += key in cells
            cell = {"points": p}
            for field, values in data.items():
                cell[field] = values[8 * c:8 * c + 8] if field == \
                    "displacement" else values[8 * c]
            cells[key] = cell
    return pieces, cells, duplicates


def read_png(path, pixels=True):
    """Width, height and rows of (R, G, B[, A]) tuples of an 8-bit RGB(A)
    or grey PNG, decoded here (zlib and the five filters of the PNG
    specification), independently of the writer; with pixels=False the
    size only (rows None)."""
    import struct
    import zlib
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "%s is not a PNG" % path
    position, idat = 8, b""
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(
                ">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        position += 12 + length
    if not pixels:
        return width, height, None
    assert depth == 8 and interlace == 0 and colour in (0, 2, 6), \
        "%s: depth %d, colour type %d, interlace %d" % (path, depth, colour,
                                                        interlace)
    channels = {0: 1, 2: 3, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for r in range(height):
        kind = raw[r * (stride + 1)]
        line = bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else
                                      b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + channels])
                     for i in range(0, stride, channels)])
        previous = line
    return width, height, rows
