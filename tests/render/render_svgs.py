#!/usr/bin/env python3
"""Rendering test of every pathref figure (spec/figures.md, rule figures.render-check).

Usage: render_svgs.py PATHREF_BINARY [SVG ...]
  Without SVG arguments: the figures the CLI writes (a fixed list of fast commands, run here into a
  temporary folder) and every SVG under docs/reproduction. Run from the repository root.

For each SVG:
  1. it parses as XML; the root declares a viewBox and a font-family (figures.font); every text's
     font size is at least 7 pt when the figure is printed 252 pt wide (figures.text);
  2. it is rendered by rsvg-convert with the viewBox padded by a margin, everything inside the
     original canvas (grown by a 1-unit antialiasing tolerance) masked out; any pixel that is not
     fully transparent is ink outside the canvas: a clipped title, label, legend or track
     (figures.canvas).
A self-test first plants those defects and requires each to be reported.

Exit 0 all pass; 1 a failure; 77 (skipped) when rsvg-convert is absent and CI is not "true"
(under CI=true a missing rsvg-convert is a failure: tools/deps.sh installs librsvg2-bin).
Python 3 standard library only.
"""
import glob
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

SVG_NS = "http://www.w3.org/2000/svg"
MARGIN = 40.0        # units of padding around the canvas
TOLERANCE = 1.0      # units of antialiasing tolerance at the canvas edge
COLUMN_PT = 252.0    # figures.text: a 3.5-inch column
MIN_PT = 7.0


def die(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def png_pixels_nonzero(png):
    """Whether any pixel of the PNG is not all-zero (transparent black). A row of zero bytes stays
    zero under every PNG filter (None, Sub, Up, Average, Paeth), so after decompression the image is
    fully transparent iff every byte except the per-row filter-type bytes is zero."""
    if png[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width, height, bpp = 8, [], 0, 0, 4
    while pos < len(png):
        (length,) = struct.unpack(">I", png[pos:pos + 4])
        kind = png[pos + 4:pos + 8]
        data = png[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", data[:10])
            channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour]
            bpp = max(1, channels * depth // 8)
        elif kind == b"IDAT":
            idat.append(data)
        pos += 12 + length
    raw = zlib.decompress(b"".join(idat))
    stride = width * bpp + 1
    count = 0
    for y in range(height):
        row = raw[y * stride + 1:(y + 1) * stride]
        count += len(row) - row.count(0)
        if count:
            return True
    return False


def viewbox(root):
    vb = root.get("viewBox")
    if vb is None:
        return None
    parts = [float(v) for v in re.split(r"[ ,]+", vb.strip())]
    return parts if len(parts) == 4 else None


def check_structure(path, root):
    """figures.font, figures.text: viewBox, font-family, text sizes."""
    problems = []
    if root.tag != f"{{{SVG_NS}}}svg":
        problems.append(f"root is {root.tag}, not svg")
    vb = viewbox(root)
    if vb is None:
        problems.append("no viewBox on the root")
    if not root.get("font-family"):
        problems.append("no font-family on the root")
    if vb is not None:
        min_size = MIN_PT * vb[2] / COLUMN_PT
        def walk(el, size):
            fs = el.get("font-size")
            if fs is not None:
                size = float(re.sub(r"(px)?$", "", fs))
            if el.tag == f"{{{SVG_NS}}}text" and "".join(el.itertext()).strip() and size < min_size - 1e-9:
                problems.append(f"text '{''.join(el.itertext())[:30]}' of size {size:g} < {min_size:.2f} "
                                f"(7 pt at {COLUMN_PT:g} pt width)")
            for child in el:
                walk(child, size)
        walk(root, 16.0)
    return problems[:5]


def ink_outside(path, rsvg, work):
    """Renders `path` with the viewBox padded by MARGIN and the canvas masked out; returns whether any
    ink falls outside the canvas."""
    ET.register_namespace("", SVG_NS)
    tree = ET.parse(path)
    root = tree.getroot()
    x, y, w, h = viewbox(root)
    m = MARGIN
    children = list(root)
    for c in children:
        root.remove(c)
    defs = ET.SubElement(root, f"{{{SVG_NS}}}defs")
    mask = ET.SubElement(defs, f"{{{SVG_NS}}}mask", {"id": "render-check-mask", "maskUnits": "userSpaceOnUse",
                                                       "x": str(x - m), "y": str(y - m), "width": str(w + 2 * m),
                                                       "height": str(h + 2 * m)})
    ET.SubElement(mask, f"{{{SVG_NS}}}rect", {"x": str(x - m), "y": str(y - m), "width": str(w + 2 * m),
                                              "height": str(h + 2 * m), "fill": "white"})
    t = TOLERANCE
    ET.SubElement(mask, f"{{{SVG_NS}}}rect", {"x": str(x - t), "y": str(y - t), "width": str(w + 2 * t),
                                              "height": str(h + 2 * t), "fill": "black"})
    g = ET.SubElement(root, f"{{{SVG_NS}}}g", {"mask": "url(#render-check-mask)"})
    for c in children:
        g.append(c)
    root.set("viewBox", f"{x - m} {y - m} {w + 2 * m} {h + 2 * m}")
    root.set("width", str(w + 2 * m))
    root.set("height", str(h + 2 * m))
    padded = os.path.join(work, "padded.svg")
    tree.write(padded, encoding="utf-8", xml_declaration=False)
    png = subprocess.run([rsvg, "-f", "png", padded], check=True, capture_output=True).stdout
    return png_pixels_nonzero(png)


def check(path, rsvg, work):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        return [f"not well-formed XML: {e}"]
    problems = check_structure(path, root)
    if viewbox(root) is not None:
        try:
            if ink_outside(path, rsvg, work):
                problems.append("ink outside the canvas (rendered with a padded viewBox)")
        except subprocess.CalledProcessError as e:
            problems.append(f"rsvg-convert failed: {e.stderr.decode(errors='replace')[:200]}")
    return problems


def self_test(rsvg, work):
    """The checker must report planted defects and pass a clean figure."""
    head = ('<svg xmlns="http://www.w3.org/2000/svg" width="504" height="100" viewBox="0 0 504 100"{font}>'
            '<rect x="0" y="0" width="504" height="100" fill="white"/>')
    cases = {
        "clean": (head.format(font=' font-family="DejaVu Sans, sans-serif"') +
                  '<text x="10" y="50" font-size="14">inside</text></svg>', False),
        "text past the right edge": (head.format(font=' font-family="DejaVu Sans, sans-serif"') +
                                     '<text x="480" y="50" font-size="14">outside the canvas</text></svg>', True),
        "line above the top": (head.format(font=' font-family="DejaVu Sans, sans-serif"') +
                               '<polyline points="10,-5 100,50" stroke="black" fill="none"/></svg>', True),
        "no font-family": (head.format(font="") + '<text x="10" y="50" font-size="14">a</text></svg>', True),
        "tiny text": (head.format(font=' font-family="DejaVu Sans, sans-serif"') +
                      '<text x="10" y="50" font-size="9">small</text></svg>', True),
    }
    for name, (text, bad) in cases.items():
        p = os.path.join(work, "planted.svg")
        with open(p, "w", encoding="utf-8") as f:
            f.write(text)
        reported = bool(check(p, rsvg, work))
        if reported != bad:
            die(f"self-test '{name}': the checker {'missed' if bad else 'reported'} it")


def cli_figures(pathref, out):
    """The figures the CLI writes: the commands of tests/cli with --svg, fast ones."""
    d = "tests/data"
    runs = [
        ("plan-grid20.svg", ["plan", "--builtin", "grid20", "--algo", "astar", "--svg"]),
        ("plan-iha.svg", ["plan", "--builtin", "grid20", "--algo", "iha", "--seed", "1", "--svg"]),
        ("plan-movingai.svg", ["plan", "--map", f"{d}/movingai/rooms40x30.map", "--algo", "astar", "--start", "1,1",
                               "--goal", "38,28", "--svg"]),
        ("plan-kinematic.svg", ["plan", "--builtin", "grid20", "--algo", "astar-kinematic", "--svg"]),
        ("plan-srrt.svg", ["plan", "--map", f"{d}/scenes/srrt_walls.json", "--algo", "s-rrt", "--seed", "3", "--svg"]),
        ("maps-grid20.svg", ["maps", "grid20", "--svg"]),
        ("maps-shi6x6-numbers.svg", ["maps", "shi6x6", "--cell-numbers", "--svg"]),
        ("plan-shi6x6-numbers.svg", ["plan", "--builtin", "shi6x6", "--algo", "aco", "--cell-numbers", "--svg"]),
        ("inflate-ushape.svg", ["inflate", f"{d}/scenes/ushape.json", "--svg"]),
        ("simulate-fused.svg", ["simulate", f"{d}/sim/sensors2023_mixed.json", "--svg"]),
    ]
    for s in ["fig8", "side", "deadend", "overtake", "frontal", "room"]:
        runs.append((f"simulate-{s}.svg", ["simulate", f"{d}/sim/{s}.json", "--svg"]))
    files = []
    for name, args in runs:
        target = os.path.join(out, name)
        r = subprocess.run([pathref] + args + [target], capture_output=True, text=True)
        if not os.path.exists(target):
            die(f"`pathref {' '.join(args)} FILE` wrote no SVG (exit {r.returncode}): {r.stderr.strip()[:300]}")
        files.append(target)
    plan = os.path.join(out, "plan.json")
    with open(plan, "w") as f:
        subprocess.run([pathref, "plan", "--builtin", "grid20", "--algo", "astar", "--json"], stdout=f, check=True)
    target = os.path.join(out, "drive.svg")
    subprocess.run([pathref, "drive", "--path", plan, "--base", "diff", "--cell", "1", "--svg", target],
                   capture_output=True, check=True)
    files.append(target)
    return files


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    rsvg = shutil.which("rsvg-convert")
    if rsvg is None:
        if os.environ.get("CI") == "true":
            die("rsvg-convert is not installed (Debian librsvg2-bin; tools/deps.sh installs it)")
        print("SKIP: rsvg-convert is not installed (Debian librsvg2-bin)")
        return 77
    with tempfile.TemporaryDirectory() as work:
        self_test(rsvg, work)
        if len(sys.argv) > 2:
            files = sys.argv[2:]
        else:
            files = cli_figures(sys.argv[1], work) + sorted(glob.glob("docs/reproduction/**/*.svg", recursive=True))
        failed = 0
        for f in files:
            problems = check(f, rsvg, work)
            if problems:
                failed += 1
                shown = f if not f.startswith(work) else os.path.basename(f) + " (CLI)"
                print(f"FAIL {shown}: " + "; ".join(problems))
        print(f"{len(files) - failed} of {len(files)} SVGs pass (viewBox, font, text >= 7 pt at 252 pt, no ink outside)")
        return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
