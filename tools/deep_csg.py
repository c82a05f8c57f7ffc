#!/usr/bin/env python3
"""Writes the deep-structure scenes of docs/reports/deep_csg.md: CSG nested N levels, and a declared object used
many times.

  deep_csg.py redeclare N [--op union|intersection|difference|merge] [--last] > u.pov
      #declare U = sphere {...}; #for (I, 1, N) #declare U = union { object { U } sphere {...} } #end object { U }
      (--last: the previous value is the node's last child, `union { sphere {...} object { U } }`)
  deep_csg.py nested N [--op ...] [--last] > n.pov   the same tree written out as N textually nested blocks
  deep_csg.py shallow N [--op ...] [--last] > s.pov  the same spheres in one flat node (what a nested union,
                                               intersection or merge means), in the order the nested form has them
  deep_csg.py uses N > t.pov                   a textured Tree union declared once and used N times, translated
"""
import argparse
import sys

HEADER = """#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at <0, 0, 0> }
light_source { <10, 10, -10> rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
"""


def first():
    return "sphere { 0, 1.5 pigment { rgb <0.8, 0.8, 0.8> } }"


def redeclare(n, op, last=False):
    out = [HEADER, "#declare U = %s\n" % first(), "#declare I = 0;\n#while (I < %d)\n" % n]
    # The loop keeps the scene short; every turn nests the previous value one level deeper.
    if last:
        out.append("  #declare U = %s { %s object { U } }\n" % (op, loop_sphere(op)))
    else:
        out.append("  #declare U = %s { object { U } %s }\n" % (op, loop_sphere(op)))
    out.append("  #declare I = I + 1;\n#end\nobject { U }\n")
    return "".join(out)


def loop_sphere(op):
    """The sphere each turn adds, as an expression of I (so the loop writes what `nested` writes)."""
    if op == "intersection":
        return "sphere { 0, 1.5 + 0.001 * I }"
    return ("sphere { <mod(mod(I, 400), 20) * 0.2 - 1.9, div(mod(I, 400), 20) * 0.2 - 1.9, -1>, 0.08 "
            "pigment { rgb <mod(I, 7) / 7, 0.6, 0.3> } }")


def nested_sphere(i, op):
    return loop_sphere(op).replace("I", str(i))


def nested(n, op, last=False):
    out = [HEADER]
    if last:
        # Level I is `op { sphere I <level I - 1> }`, the first sphere innermost.
        for i in reversed(range(n)):
            out.append("%s {\n%s\n" % (op, nested_sphere(i, op)))
        out.append(first() + "\n")
        out.append("}\n" * n)
        return "".join(out)
    out.append("%s {\n" % op * n)
    out.append(first() + "\n")
    for i in range(n):
        out.append("%s }\n" % nested_sphere(i, op))
    return "".join(out)


def shallow(n, op="union", last=False):
    spheres = [nested_sphere(i, op) + "\n" for i in range(n)]
    if last:
        return "".join([HEADER, "%s {\n" % op] + spheres[::-1] + [first() + "\n", "}\n"])
    return "".join([HEADER, "%s {\n" % op, first() + "\n"] + spheres + ["}\n"])


def uses(n):
    side = int(n ** 0.5) + 1
    return HEADER.replace("<0, 0, -6>", "<0, 40, -60>") + """#declare Tree = union {
  cylinder { 0, <0, 1, 0>, 0.1 pigment { rgb <0.4, 0.25, 0.1> } }
  cone { <0, 0.8, 0>, 0.5, <0, 2, 0>, 0 texture { pigment { bozo color_map { [0 rgb <0, 0.4, 0>] [1 rgb <0.2, 0.8, 0.1>] } scale 0.2 } finish { phong 0.3 } } }
  sphere { <0, 0.9, 0>, 0.45 pigment { rgb <0.1, 0.5, 0.1> } }
}
#declare I = 0;
#while (I < %d)
  object { Tree translate <mod(I, %d) - %d, 0, div(I, %d) - %d> * 0.5 }
  #declare I = I + 1;
#end
""" % (n, side, side // 2, side, side // 2)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("form", choices=["redeclare", "nested", "shallow", "uses"])
    ap.add_argument("n", type=int)
    ap.add_argument("--op", default="union", choices=["union", "intersection", "difference", "merge"])
    ap.add_argument("--last", action="store_true", help="the nested node is its parent's last child, not its first")
    a = ap.parse_args()
    if a.form == "redeclare":
        sys.stdout.write(redeclare(a.n, a.op, a.last))
    elif a.form == "nested":
        sys.stdout.write(nested(a.n, a.op, a.last))
    elif a.form == "shallow":
        sys.stdout.write(shallow(a.n, a.op, a.last))
    else:
        sys.stdout.write(uses(a.n))


if __name__ == "__main__":
    main()
