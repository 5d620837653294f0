#!/bin/sh
# The evaluation behind docs/results/README.md: TOSCA (wolf, centaur, cat,
# david) and FAUST (tr_reg) in one dataset directory so retrieval ranks across
# all classes; faust_remeshed (each pose meshed on its own, .vts rows) apart.
# Run from the worktree root after building; outputs (meshes) go to $OUT, only
# the tables and plots are committed.
set -e
DATA=${DATA:-../shared/data}
OUT=${OUT:-/tmp/unfold_eval}
mkdir -p "$OUT/dataset"
for f in "$DATA"/tosca/*.off "$DATA"/faust/*.off; do ln -sf "$(realpath "$f")" "$OUT/dataset/"; done
mkdir -p "$OUT/remeshed_dataset"
for f in "$DATA"/faust_remeshed/*; do ln -sf "$(realpath "$f")" "$OUT/remeshed_dataset/"; done

# --skip_existing: a run that was stopped goes on where it was; remove $OUT
# (or a method's folders in it) after changing the code.
# Every method at the paper's resolution (surfaces simplified to ~2,000 vertices).
build/bin/unfold_batch --input_dir "$OUT/dataset" --output_dir "$OUT/2k" --skip_existing \
  --configs configs/paper.yaml,configs/default.yaml,configs/lsmds.yaml,configs/dpmu.yaml,configs/scf.yaml \
  --target_vertices 2000 --jobs 2
# Ours at full resolution: the paper's method, the integrated rotation field on
# the input's tets and the default (docs/method.md: pose invariance, contact,
# meshing), and the SCF, LSMDS and DPMU baselines (docs/baselines.md); pose
# pictures poses_<class>_<method>.png. DPMU alone takes about an hour here
# (two jobs).
build/bin/unfold_batch --input_dir "$OUT/dataset" --output_dir "$OUT/full" --skip_existing \
  --configs configs/paper.yaml,configs/invariant.yaml,configs/default.yaml,configs/scf.yaml,configs/lsmds.yaml,configs/dpmu.yaml --jobs 2
build/bin/unfold_batch --input_dir "$OUT/remeshed_dataset" --output_dir "$OUT/remeshed" --skip_existing \
  --configs configs/paper.yaml,configs/invariant.yaml,configs/default.yaml --jobs 2

# The report: Table 1-style means, the retrieval measures (NN, FT, ST, E, DCG per
# framework, icp, ort and cmbof, like Table 3), cdf_*.png and the precision-recall
# curves pr_icp.png, pr_ort.png, pr_cmbof.png.
build/bin/unfold_report --runs "$OUT/2k,$OUT/full" --labels 2k,full \
  --markdown docs/results/report.md --plots_dir docs/results
cp "$OUT"/2k/results.csv docs/results/results_2k.csv
cp "$OUT"/full/results.csv docs/results/results_full.csv
for d in 2k full; do
  for f in retrieval pose_invariance pose_pairs; do cp "$OUT/$d/$f.csv" "docs/results/${f}_$d.csv"; done
  for f in "$OUT"/$d/similarity_*.csv; do cp "$f" "docs/results/${d}_$(basename "$f")"; done
done
for f in "$OUT"/full/poses_*.png; do cp "$f" docs/results/; done
for m in paper default; do
  for f in "$OUT"/full/worst_*_$m.png "$OUT"/full/folds_*_$m.png; do cp "$f" docs/results/; done
done
for f in "$OUT"/2k/poses_*.png; do cp "$f" "docs/results/2k_$(basename "$f")"; done
for f in results pose_invariance pose_pairs; do cp "$OUT/remeshed/$f.csv" "docs/results/${f}_remeshed.csv"; done
