"""Compares two unfold_batch output directories: every CSV value (numbers within a
relative tolerance, the seconds columns aside, text exactly) and every output mesh
(same faces, vertices within a tolerance relative to the mesh's bounding-box
diagonal). Prints each file compared; exits 1 naming the differences.

Usage: python3 compare_runs.py A B [--csv_tolerance 1e-7] [--mesh_tolerance 1e-8]
"""
import argparse
import csv
import math
import pathlib
import sys


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare_csv(a, b, tolerance):
    rows_a = list(csv.reader(a.open()))
    rows_b = list(csv.reader(b.open()))
    if len(rows_a) != len(rows_b) or rows_a[:1] != rows_b[:1]:
        return ["different rows or header"], 0.0
    header = rows_a[0]
    problems = []
    worst = 0.0
    for line, (ra, rb) in enumerate(zip(rows_a[1:], rows_b[1:]), start=2):
        if len(ra) != len(rb):
            problems.append(f"line {line}: different field counts")
            continue
        for column, (fa, fb) in enumerate(zip(ra, rb)):
            name = header[column] if column < len(header) else str(column)
            if name == "seconds" or name.startswith("seconds_"):
                continue
            xa, xb = number(fa), number(fb)
            if xa is None or xb is None or math.isnan(xa) or math.isnan(xb):
                if fa != fb:
                    problems.append(f"line {line} {name}: '{fa}' vs '{fb}'")
                continue
            scale = max(abs(xa), abs(xb))
            relative = abs(xa - xb) / scale if scale > 0 else 0.0
            worst = max(worst, relative)
            if relative > tolerance:
                problems.append(f"line {line} {name}: {fa} vs {fb} (relative {relative:.2e})")
    return problems, worst


def read_off(path):
    tokens = []
    for line in path.open():
        tokens += line.split("#")[0].split()
    if tokens[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    vertices = [tuple(map(float, tokens[at + 3 * i:at + 3 * i + 3])) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(tokens[at])
        faces.append(tuple(tokens[at + 1:at + 1 + k]))
        at += 1 + k
    return vertices, faces


def compare_mesh(a, b, tolerance):
    va, fa = read_off(a)
    vb, fb = read_off(b)
    if len(va) != len(vb) or fa != fb:
        return ["different vertex counts or faces"], 0.0
    lo = [min(v[i] for v in va) for i in range(3)]
    hi = [max(v[i] for v in va) for i in range(3)]
    size = math.dist(lo, hi)
    largest = max(math.dist(p, q) for p, q in zip(va, vb)) / size
    if largest > tolerance:
        return [f"a vertex moved {largest:.2e} of the size"], largest
    return [], largest


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a", type=pathlib.Path)
    parser.add_argument("b", type=pathlib.Path)
    parser.add_argument("--csv_tolerance", type=float, default=1e-7)
    parser.add_argument("--mesh_tolerance", type=float, default=1e-8)
    args = parser.parse_args()

    def files(root):
        return {p.relative_to(root) for p in root.rglob("*")
                if p.suffix in (".csv", ".off") and p.is_file()}

    in_a, in_b = files(args.a), files(args.b)
    failed = False
    for only, where in ((in_a - in_b, args.a), (in_b - in_a, args.b)):
        for path in sorted(only):
            print(f"compare_runs: only in {where}: {path}")
            failed = True
    for path in sorted(in_a & in_b):
        if path.suffix == ".csv":
            problems, worst = compare_csv(args.a / path, args.b / path, args.csv_tolerance)
            what = "relative"
        else:
            problems, worst = compare_mesh(args.a / path, args.b / path, args.mesh_tolerance)
            what = "of the size"
        print(f"compare_runs: {path}: largest difference {worst:.1e} {what}"
              + ("" if not problems else "  DIFFERENT: " + "; ".join(problems[:3])))
        failed = failed or bool(problems)
    print(f"compare_runs: {len(in_a & in_b)} files compared, "
          + ("DIFFERENCES" if failed else "all within tolerance"))
    return 1 if failed or not in_a else 0


if __name__ == "__main__":
    sys.exit(main())
