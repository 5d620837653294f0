# Shell code shared by scripts/slurm/submit and scripts/slurm/match (sourced, after
# `set -euo pipefail`): their messages, checks and submissions. Uses the script's
# variables prog (its name in messages), out (its output directory), made_out (set
# if the script made it) and scratch (a temporary directory it removes on exit).
# shellcheck shell=bash disable=SC2154  # those variables are the sourcing script's

# A one-line error; exit 2: the command is refused, nothing is queued.
die() {
  echo "$prog: $*" >&2
  exit 2
}

# The script's header comment, its usage.
print_help() {
  sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'
}

need_slurm_commands() {
  local command
  for command in sbatch squeue; do
    command -v "$command" >/dev/null || die "$command not found on PATH (Slurm's client commands)"
  done
}

# Dies with message $2 unless $1 is an integer >= 1.
need_count() {
  if [[ ! $1 =~ ^[0-9]+$ ]] || ((10#$1 < 1)); then die "$2"; fi
}

# The jobs' name, one per output directory, so that squeue finds the jobs of a
# submission on it.
job_name() {
  echo "unfold-$(echo "$1" | sha256sum | cut -c1-12)"
}

# One output directory, one command: refuses to mix results of different inputs,
# configs or options (the record file $1 holds the command that wrote them, $2 is
# this one's), and to write beside a submission still queued or running (jobs named $3).
check_output() {
  local running
  if [[ -f $1 ]] && [[ $(<"$1") != "$2" ]]; then
    die "$out holds the results of another command (see $1); use another OUT"
  fi
  running=$(squeue -h -n "$3" -o %i | sort -u | paste -sd " ")
  [[ -z $running ]] || die "jobs $running of a submission on $out are still queued or running"
}

# Slurm's verdict on the options (partition, time, memory) before anything is
# written: a job running script $1 with sbatch options $2...
check_job() {
  local script=$1 err
  shift
  if ! err=$(sbatch --test-only "$@" --output /dev/null <<<"$script" 2>&1 >/dev/null) ||
    [[ $err == *error* ]]; then
    die "sbatch refuses the job: $(grep -m1 error <<<"$err" || echo "$err")"
  fi
}

# Queues script $1 with sbatch options $2... and sets job to its id. A refused
# submission leaves no job queued before it, and no output directory it made.
submitted=()
queue_job() {
  local script=$1 id
  shift
  if ! id=$(sbatch --parsable "$@" <<<"$script" 2>"$scratch/err"); then
    if ((${#submitted[@]})); then scancel "${submitted[@]}" 2>/dev/null || true; fi
    if [[ -n ${made_out:-} ]]; then rm -rf "$out"; fi
    die "sbatch refused: $(grep -m1 . "$scratch/err")"
  fi
  job=${id%%;*}
  submitted+=("$job")
}
