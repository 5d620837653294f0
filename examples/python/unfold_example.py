"""The README's Python example: unfold_example.py [input mesh [output mesh]].

Without arguments it unfolds the built-in demo shape into canonical.off. On the
same input its output file is the command line's (`unfold --input X --output Y`).
"""
import sys, unfold
V, F = unfold.read_mesh(sys.argv[1]) if len(sys.argv) > 1 else unfold.demo_shape()
r = unfold.unfold(V, F)  # config keys as keywords, e.g. unfold.unfold(V, F, k_iter=20)
unfold.write_mesh(sys.argv[2] if len(sys.argv) > 2 else "canonical.off", r.vertices, r.faces)
print(f"E_rig {r.metrics['E_rig']:.4f}, E_str {r.metrics['E_str']:.4f}, {len(r.tets)} tets")
