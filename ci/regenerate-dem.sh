#!/usr/bin/env bash
# Regenerate the DEM (LIGGGHTS) references in reference/dem/*.csv:
#   1.-2. unless DEM_COLLAPSE=0 (e.g. to regenerate the wall alone):
#   1. angle-of-repose calibration (ledge test) at the chosen micro-parameters,
#      two seeds -> reference/dem/calibration_repose_seed*.csv
#   2. quasi-2D granular column collapse, Bui et al. (2008) set-up, a = 0.5
#      (L0 = 0.2 m, H0 = 0.1 m)            -> reference/dem/collapse_a0.5.csv
#      and, unless DEM_ONLY_A05=1, a = 1 and a = 2 (H0 = 0.1 m, L0 = 0.1 / 0.05 m)
#                                           -> reference/dem/collapse_a1.csv, collapse_a2.csv
#   3. unless DEM_SENSITIVITY=0: sensitivity pair with mu = 0.4, mu_r = 0.1
#      -> reference/dem/calibration_repose_mu0.4_mur0.1.csv, collapse_a0.5_mu0.4_mur0.1.csv
#   4. unless DEM_WALL=0: smooth retaining wall translated away from (active, 10 mm) and into
#      (passive, 30 mm) a 0.3 m x 0.1 m backfill at 10 mm/s
#      -> reference/dem/retaining_wall_{active,passive}.csv and ..._slip.csv (~10 min each)
# Not part of the default tests (ci/test.sh); the SPH verification cases only
# read the committed CSVs.  Takes a few minutes on 2 cores (serial LIGGGHTS).
# Extra LIGGGHTS variable overrides can be passed via DEM_VARS, e.g.
#   DEM_VARS="-var d 0.003" bash ci/regenerate-dem.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEM="$ROOT/reference/dem"
PY="${PYTHON:-/usr/bin/python3}"
LIGGGHTS="${LIGGGHTS:-liggghts}"

if ! command -v "$LIGGGHTS" >/dev/null 2>&1; then
  cat >&2 <<'EOF'
regenerate-dem.sh: LIGGGHTS not found (looked for `liggghts` on PATH).
Install it with
    sudo apt-get install liggghts        # Debian/Ubuntu package, LIGGGHTS-PUBLIC 3.8.0
or point LIGGGHTS=/path/to/liggghts at a build of your own.
Nothing was changed: the SPH verification cases keep using the committed
reference/dem/*.csv files.
EOF
  exit 1
fi
if ! "$PY" -c 'import numpy' 2>/dev/null; then
  echo "regenerate-dem.sh: $PY lacks numpy (set PYTHON=/path/to/python3 with numpy)" >&2
  exit 1
fi

WORK="$(mktemp -d "${TMPDIR:-/tmp}/geosph-dem.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
DATE="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
MU=0.15
MUR=0.02
CAL_NOTE="sliding friction mu = $MU and rolling friction (cdt) mu_r = $MUR chosen so that the ledge angle of repose (calibration.in) ~ the SPH friction angle 19.8 deg, assuming angle of repose ~ friction angle for a cohesionless material; see reference/dem/README.md and calibration_repose_seed*.csv"
# shellcheck disable=SC2206
EXTRA=(${DEM_VARS:-})

run() {  # run NAME INPUT [-var ...]
  local name="$1" input="$2"; shift 2
  local cmd=("$LIGGGHTS" -in "$input" -var mu "$MU" -var mur "$MUR" "$@" "${EXTRA[@]}" -var out "$name" -log "$name.log")
  echo "== $name: ${cmd[*]}" >&2
  # NB: do not use `-screen none` (LIGGGHTS 3.8.0 segfaults in insert/pack); send the screen to a file
  ( cd "$WORK" && "${cmd[@]}" > "$name.screen" 2>&1 ) || { tail -20 "$WORK/$name.screen" >&2; exit 1; }
  CMDLINE="liggghts -in reference/dem/$(basename "$input") -var mu $MU -var mur $MUR $*${EXTRA[*]:+ ${EXTRA[*]}} -var out $name -log $name.log"
}

# Calibration and collapse (skip with DEM_COLLAPSE=0, e.g. to regenerate the wall alone).
if [ "${DEM_COLLAPSE:-1}" = "1" ]; then
  cases=("0.5 0.2")
  [ "${DEM_ONLY_A05:-0}" = "1" ] || cases+=("1 0.1" "2 0.05")
  for seed in 15485863 32452867; do
    run "repose_$seed" "$DEM/calibration.in" -var seed "$seed"
    "$PY" "$DEM/postprocess.py" repose "$WORK/repose_${seed}_final.dump" --log "$WORK/repose_$seed.log" \
      --input "$DEM/calibration.in" --command "$CMDLINE" --date "$DATE" --calibration-note "$CAL_NOTE" \
      -o "$DEM/calibration_repose_seed$seed.csv"
  done
  for c in "${cases[@]}"; do
    set -- $c
    a="$1"; L0="$2"
    run "collapse_a$a" "$DEM/collapse_2d.in" -var L0 "$L0" -var H0 0.1
    "$PY" "$DEM/postprocess.py" collapse "$WORK/collapse_a${a}_final.dump" --initial "$WORK/collapse_a${a}_initial.dump" \
      --log "$WORK/collapse_a$a.log" --input "$DEM/collapse_2d.in" --command "$CMDLINE" --date "$DATE" \
      --calibration-note "$CAL_NOTE" -o "$DEM/collapse_a$a.csv"
  done
fi

# Sensitivity set (skip with DEM_SENSITIVITY=0): stiffer micro-parameters
# mu = 0.4, mu_r = 0.1 (ledge repose angle ~30 deg), a = 0.5 only.
if [ "${DEM_SENSITIVITY:-1}" = "1" ]; then
  MU=0.4
  MUR=0.1
  SENS_NOTE="SENSITIVITY case, NOT calibrated to phi = 19.8 deg: mu = $MU, mu_r = $MUR (ledge repose angle in calibration_repose_mu0.4_mur0.1.csv); see reference/dem/README.md"
  run "repose_mu0.4_mur0.1" "$DEM/calibration.in" -var seed 15485863
  "$PY" "$DEM/postprocess.py" repose "$WORK/repose_mu0.4_mur0.1_final.dump" --log "$WORK/repose_mu0.4_mur0.1.log" \
    --input "$DEM/calibration.in" --command "$CMDLINE" --date "$DATE" --calibration-note "$SENS_NOTE" \
    -o "$DEM/calibration_repose_mu0.4_mur0.1.csv"
  run "collapse_a0.5_mu0.4_mur0.1" "$DEM/collapse_2d.in" -var L0 0.2 -var H0 0.1
  "$PY" "$DEM/postprocess.py" collapse "$WORK/collapse_a0.5_mu0.4_mur0.1_final.dump" \
    --initial "$WORK/collapse_a0.5_mu0.4_mur0.1_initial.dump" --log "$WORK/collapse_a0.5_mu0.4_mur0.1.log" \
    --input "$DEM/collapse_2d.in" --command "$CMDLINE" --date "$DATE" --calibration-note "$SENS_NOTE" \
    -o "$DEM/collapse_a0.5_mu0.4_mur0.1.csv"
fi
# Retaining wall (skip with DEM_WALL=0): calibrated micro-parameters again.
if [ "${DEM_WALL:-1}" = "1" ]; then
  MU=0.15
  MUR=0.02
  for spec in "active -0.01 0.01" "passive 0.01 0.03"; do
    set -- $spec
    mode="$1"; vw="$2"; dmax="$3"
    run "wall_$mode" "$DEM/retaining_wall_2d.in" -var vw "$vw" -var dmax "$dmax"
    "$PY" "$DEM/postprocess.py" wall "$WORK/wall_${mode}_final.dump" --initial "$WORK/wall_${mode}_initial.dump" \
      --force "$WORK/wall_${mode}_force.txt" --log "$WORK/wall_$mode.log" --input "$DEM/retaining_wall_2d.in" \
      --command "$CMDLINE" --date "$DATE" --calibration-note "$CAL_NOTE" -o "$DEM/retaining_wall_$mode.csv"
  done
fi
echo "DEM references written to $DEM" >&2
