#!/usr/bin/env python3
"""Write the parameter file of the MCA benchmark block.

usage: make_block.py CELLS_XY CELLS_Z elastic|plastic STEPS OUTPUT_DIR > block.prm

An FCC block of CELLS_XY x CELLS_XY x CELLS_Z cells (4 automata per cell,
d = 1 mm), periodic in x and y, all pairs bonded; the top layer moves down
at 0.05 m/s and the bottom layer is fixed (a slow compression). 'plastic'
uses linear hardening with a yield stress of 1 MPa, so that the plastic
pass (trial tensors and radial return) runs and automata yield. No
particle output; one series row at the end.
"""
import math
import sys

n, nz, kind, steps, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3], int(sys.argv[4]), sys.argv[5]
d = 1e-3
a = d * math.sqrt(2)
L, H = n * a, nz * a
c_p = 5810.6
dt = 0.2 * d / c_p
print(f"""# MCA benchmark block: {n} x {n} x {nz} FCC cells, {kind}, {steps} steps
set Problem = mca
set Output directory = {out}
subsection Geometry
  set Automaton size = {d}
  set Domain lower = 0, 0, {-0.5 * a}
  set Domain upper = {L!r}, {L!r}, {H + 0.5 * a!r}
  set Periodic x = true
  set Periodic y = true
  set Bodies = 0 0 0 {L!r} {L!r} {H!r} steel
end
subsection Materials
  subsection Steel
    set Hardening = {"linear" if kind == "plastic" else "elastic"}
    set Yield stress = 1e6
  end
end
subsection Interaction
  set Rotations = true
  set Plasticity = {"true" if kind == "plastic" else "false"}
end
subsection Boundary conditions
  set Groups = top velocity -1 -1 {H - 0.3 * a!r} 1 1 1 * * -0.05; bottom fixed -1 -1 -1 1 1 {0.3 * a!r}
end
subsection Time
  set End time = {steps * dt * 0.999999!r}
  set Time step = {dt!r}
end
subsection Output
  set Write particles = false
  set Series interval = {steps * dt!r}
end
""")
