#!/usr/bin/env bash
# check-outputs.sh — proves a refactor moved nothing: record every output of the `vantage`
# command with the old binary, record them again with the new one, compare.
#
#   scripts/check-outputs.sh record VANTAGE_BINARY OUT_DIR   # OUT_DIR must be new or empty
#   scripts/check-outputs.sh compare DIR_A DIR_B             # exit 0: the same; 1: a listing
#
#   e.g.  scripts/check-outputs.sh record /tmp/vantage-base /tmp/golden-base
#         scripts/check-outputs.sh record build/cli/vantage /tmp/golden-new
#         scripts/check-outputs.sh compare /tmp/golden-base /tmp/golden-new
#
# `record` runs the binary from the repository root (the parent of this script's directory) on
# every bundled example (examples/layouts, examples/tools, examples/bodies,
# examples/correspondences) with every subcommand that applies: the text report and --json of
# analyze (also --dropout, --seen-whole, --verbose, --swaps, --pair-weighting, --no-crosscheck),
# weights, orient and pose (every method on every correspondence file), design (--add 2, --write),
# place (small: 4 markers among 100 sampled sites, with a workspace; and --sites), crb (with
# --direction, --sweep-distance, --sweep-tags), tre (--fle-rms, --fle-sigma, --direction, a small
# seeded Monte Carlo), ident, simulate (small, seeded, --threads 1: affine and pinhole cameras,
# --csv, --shard/--merge), layout board and layout convert, every experiment with --quick, and
# every figure family of plot (layout figures with the visibility and placement maps, --design,
# --crb, --tre, --experiment); then --help of every subcommand, --version, and bad inputs (exit 2
# with one line on stderr). For call NAME it writes OUT_DIR/NAME.cmd (the arguments), NAME.out
# (stdout), NAME.err (stderr) and NAME.rc (exit status); files a call writes (--out, --write,
# --csv, figure and experiment directories) go to a scratch directory and are copied into
# OUT_DIR/NAME.files/: every text file (CSV, JSON, Markdown, .ini) verbatim, and every image
# (PNG, SVG) as its SHA-256 in NAME.files/images.sha256.
# Time: `record` makes 454 calls in about 55 s of wall time (45 s CPU) on this 2-core machine with
# the RelWithDebInfo build, measured while a two-job build ran beside it; it writes about 50 MB
# (mostly the plot CSVs). `compare` takes a second. Each call is capped at 300 s by `timeout` (a
# hang shows up as exit status 124 in NAME.rc).
#
# What is normalised (after the calls, in OUT_DIR only; each found by recording twice with the
# same binary and comparing, nothing else is touched and no computed number is masked):
#   - paths: the scratch directory becomes @SCRATCH@ (a fresh mktemp name on every run, echoed in
#     "written: ...", the figure lists, --out and error messages), and, should they appear, OUT_DIR
#     @OUT@, the binary @VANTAGE@ and the repository root @REPO@ (a layout that place, design
#     --write or layout convert writes names its body mesh by a path relative to the written file,
#     "../../../work/main/examples/bodies/...", which becomes "../../..@REPO@/examples/...");
#   - wall-clock times, which differ on every run: in simulate the per-solve time (JSON
#     "time_us" {median, mean, p95, max} and per-trial "time_us" lists, the --csv column time_us,
#     the text line "time per solve (us)"); in experiment the run time (JSON "seconds", the text
#     line "(N s)"), the time_us_median column of the sweep CSVs, the "time ..." columns of the
#     summary tables (summary.md, stdout), and the hash of the figure that draws those times
#     (wu_points_time.png; its CSV is kept with the time column masked). Each masked value
#     becomes @TIME@; the counts beside them ("count") stay.
#   Nothing thread-dependent was found: every command that takes --threads is run with
#   --threads 1 anyway, and plot (which has no --threads) gave the same CSVs and PNGs on every run.
#
# Needs bash, coreutils (timeout, sha256sum), diff and python3 (the normalisation).

set -uo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)" || exit 2
readonly REPO
readonly CALL_TIMEOUT=300

die() {
  echo "check-outputs.sh: $*" >&2
  exit 2
}

usage() {
  sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

# ---------------------------------------------------------------------------------------------
# record

VANTAGE=""
OUT=""
SCRATCH=""
CALLS=0

# run NAME ARGS...: `vantage ARGS` from the repository root; stdout, stderr and exit status into
# OUT/NAME.out, .err, .rc, the arguments into OUT/NAME.cmd.
run() {
  local name=$1
  shift
  mkdir -p "$OUT/$(dirname "$name")"
  printf '%s\n' "$*" >"$OUT/$name.cmd"
  timeout "$CALL_TIMEOUT" "$VANTAGE" "$@" </dev/null >"$OUT/$name.out" 2>"$OUT/$name.err"
  echo $? >"$OUT/$name.rc"
  CALLS=$((CALLS + 1))
}

# keep NAME PATH...: copies the files or directories a call wrote into OUT/NAME.files/ (text
# verbatim, images as hashes); a PATH that does not exist is listed in missing.txt.
keep() {
  local name=$1
  shift
  local dest="$OUT/$name.files" path base
  mkdir -p "$dest"
  for path in "$@"; do
    base=$(basename "$path")
    if [[ -d $path ]]; then
      copy_tree "$path" "$dest/$base"
    elif [[ -f $path ]]; then
      copy_file "$path" "$dest" "$base"
    else
      echo "$base" >>"$dest/missing.txt"
    fi
  done
}

# copy_file SRC DEST_DIR NAME: a text file verbatim, an image as a line of DEST_DIR/images.sha256.
copy_file() {
  local src=$1 dest=$2 name=$3
  case "$name" in
  *.png | *.svg | *.pdf | *.PNG | *.SVG | *.PDF)
    printf '%s  %s\n' "$(sha256sum <"$src" | cut -d' ' -f1)" "$name" >>"$dest/images.sha256"
    ;;
  *)
    cp "$src" "$dest/$name"
    ;;
  esac
}

# copy_tree SRC DEST: every file under SRC, sorted, by copy_file.
copy_tree() {
  local src=$1 dest=$2 rel
  mkdir -p "$dest"
  while IFS= read -r rel; do
    mkdir -p "$dest/$(dirname "$rel")"
    copy_file "$src/$rel" "$dest/$(dirname "$rel")" "$(basename "$rel")"
  done < <(cd "$src" && find . -type f | sed 's|^\./||' | LC_ALL=C sort)
}

# The bundled examples (filled by record, from the repository root).
LAYOUTS=()
TOOLS=()
CORRESPONDENCES=()
POSE_METHODS=(affine affine-refined perspective standard full3d oi-foam oi-svd two-view
  haralick-2d haralick-3d)

# The stem of an example: examples/tools/passive4_150.ini -> passive4_150.ini (the extension stays:
# drone.json and a drone.csv would otherwise collide).
stem() { basename "$1"; }

# A camera distance for the pose CRB of each point layout: about ten times its radius.
crb_distance() {
  case "$(stem "$1")" in
  apriltag_cube.yaml) echo 2 ;;
  docking_target.json) echo 1.5 ;;
  drone.json) echo 2.5 ;;
  mocap_rigid_body.csv) echo 1 ;;
  satellite.json) echo 30 ;;
  surgical_tool.json) echo 900 ;;
  cube_sites.json) echo 6 ;;
  *) echo 500 ;;  # the tools, in mm
  esac
}

record_help() {
  run help/root --help
  run help/version --version
  local sub
  for sub in analyze orient design place weights pose layout simulate experiment plot crb tre \
    ident; do
    run "help/$sub" "$sub" --help
  done
  run help/layout-board layout board --help
  run help/layout-convert layout convert --help
}

record_analyze() {
  local f s
  for f in "${LAYOUTS[@]}" "${TOOLS[@]}" examples/bodies/cube_sites.json; do
    s=$(stem "$f")
    run "analyze/$s" analyze "$f"
    run "analyze/$s.json" analyze "$f" --json
  done
  # The layouts with normals: the same seen whole.
  for f in examples/layouts/{satellite,drone,docking_target,surgical_tool}.json \
    examples/layouts/apriltag_cube.yaml examples/tools/{ndi_like,five_marker}.json; do
    s=$(stem "$f")
    run "analyze/$s.seen-whole" analyze "$f" --seen-whole
    run "analyze/$s.seen-whole.json" analyze "$f" --seen-whole --json
  done
  for f in examples/layouts/{note3_four_vectors,drone,surgical_tool}.json \
    examples/layouts/mocap_rigid_body.csv examples/layouts/apriltag_cube.yaml \
    examples/tools/ndi_like.json; do
    s=$(stem "$f")
    run "analyze/$s.dropout" analyze "$f" --dropout
    run "analyze/$s.dropout.json" analyze "$f" --dropout --json
  done
  run analyze/drone.json.seen-whole.dropout analyze examples/layouts/drone.json --seen-whole \
    --dropout --json
  run analyze/satellite.json.verbose analyze examples/layouts/satellite.json --verbose --swaps 8
  run analyze/mocap.arithmetic analyze examples/layouts/mocap_rigid_body.csv \
    --pair-weighting arithmetic --swaps 2 --no-crosscheck --json
  run analyze/apriltag.centres analyze examples/layouts/apriltag_cube.yaml --tag-points centres
  run analyze/drone.body-options analyze examples/layouts/drone.json --cone-deg 60 \
    --min-visible 4 --json
  run analyze/mocap.radial analyze examples/layouts/mocap_rigid_body.csv --normals radial \
    --cone-deg 100
  run analyze/capsule-body analyze examples/bodies/cube_sites.json \
    --body examples/bodies/capsule.obj --workspace 0,0,1,60 --json
}

record_weights() {
  local f s
  for f in "${LAYOUTS[@]}" "${TOOLS[@]}" examples/bodies/cube_sites.json; do
    s=$(stem "$f")
    run "weights/$s" weights "$f"
    run "weights/$s.json" weights "$f" --json
  done
}

record_orient() {
  local f s m
  for f in "${CORRESPONDENCES[@]}"; do
    s=$(stem "$f")
    for m in qmethod svd foam; do
      run "orient/$s.$m" orient "$f" --method "$m"
      run "orient/$s.$m.json" orient "$f" --method "$m" --json
    done
  done
}

record_pose() {
  local f s m
  for f in "${CORRESPONDENCES[@]}"; do
    s=$(stem "$f")
    for m in "${POSE_METHODS[@]}"; do
      run "pose/$s.$m" pose "$f" --method "$m"
      run "pose/$s.$m.json" pose "$f" --method "$m" --json
    done
  done
  local a=examples/correspondences/affine_pose.json
  for m in affine affine-refined standard perspective; do
    run "pose/affine_pose.json.$m.focal" pose "$a" --method "$m" --focal 1000 \
      --principal-point 0 0 --json
  done
  for m in all spanning; do
    run "pose/affine_pose.json.affine.$m" pose "$a" --method affine --free-vectors "$m" --json
    run "pose/perspective_pose.json.affine.$m" pose examples/correspondences/perspective_pose.json \
      --method affine --free-vectors "$m"
  done
  # No bundled example is planar with a 2-D image (haralick-2d): this one is 30 deg and (0.3, -0.2).
  local planar="$SCRATCH/planar_2d.json"
  printf '%s\n' '{"name": "planar, 30 deg", "model": [[0, 0, 0], [1, 0, 0], [0, 1, 0],' \
    '[1, 1, 0], [0.5, 0.2, 0], [-0.4, 0.7, 0]], "image": [[0.3, -0.2], [1.166025403784, 0.3],' \
    '[-0.2, 0.666025403784], [0.666025403784, 1.166025403784], [0.633012701892, 0.223205080757],' \
    '[-0.396410161514, 0.206217782649]]}' >"$planar"
  run pose/planar_2d.haralick-2d pose "$planar" --method haralick-2d
  run pose/planar_2d.haralick-2d.json pose "$planar" --method haralick-2d --json
  run pose/two_view.json.two-view.focal pose examples/correspondences/two_view.json \
    --method two-view --focal 800 --principal-point 320 240 --json
}

record_design() {
  local w="$SCRATCH/design"
  mkdir -p "$w"
  run design/note3_four_vectors design examples/layouts/note3_four_vectors.json --add 2
  run design/note3_four_vectors.json design examples/layouts/note3_four_vectors.json --add 2 \
    --json
  run design/triad.write design examples/layouts/triad.json --add 2 --write "$w/triad2.json" \
    --json
  keep design/triad.write "$w/triad2.json"
  run design/coplanar_fan design examples/layouts/coplanar_fan.json --add 1
  run design/triad.plot design examples/layouts/triad.json --add 3 --plot "$w/triad-plot"
  keep design/triad.plot "$w/triad-plot"
  run design/drone design examples/layouts/drone.json --add 2 --no-direct
  run design/drone.json design examples/layouts/drone.json --add 2 --json
  run design/drone.budget design examples/layouts/drone.json --add 1 --search-budget 0 \
    --margin 0.5 --no-direct --json
  run design/satellite.candidates design examples/layouts/satellite.json --add 2 \
    --candidates-only --write "$w/satellite2.json"
  keep design/satellite.candidates "$w/satellite2.json"
  run design/satellite.candidates.json design examples/layouts/satellite.json --add 2 \
    --candidates-only --json
  run design/mocap.csv design examples/layouts/mocap_rigid_body.csv --add 1 --no-direct \
    --min-distance-difference 0.0005 --write "$w/mocap1.csv"
  keep design/mocap.csv "$w/mocap1.csv"
  run design/ndi_like design examples/tools/ndi_like.json --add 1 --no-direct --json
}

record_place() {
  local w="$SCRATCH/place"
  mkdir -p "$w"
  local small=(--markers 4 --candidates 100 --random-trials 100 --seed 3 --threads 1)
  run place/capsule place examples/bodies/capsule.obj "${small[@]}" --workspace 0,0,1,60 \
    --out "$w/capsule4.json"
  keep place/capsule "$w/capsule4.json"
  run place/capsule.json place examples/bodies/capsule.obj "${small[@]}" --workspace 0,0,1,60 \
    --out "$w/capsule4j.json" --json
  keep place/capsule.json "$w/capsule4j.json"
  run place/satellite place examples/bodies/satellite.obj "${small[@]}" --workspace 0,0,1,45 \
    --cone-deg 80 --out "$w/satellite4.json"
  keep place/satellite "$w/satellite4.json"
  run place/satellite.json place examples/bodies/satellite.obj "${small[@]}" \
    --workspace 0,0,1,45 --cone-deg 80 --out "$w/satellite4j.json" --json
  keep place/satellite.json "$w/satellite4j.json"
  run place/cube_sites place --sites examples/bodies/cube_sites.json --markers 4 \
    --random-trials 100 --threads 1 --out "$w/cube4.json"
  keep place/cube_sites "$w/cube4.json"
  run place/cube_sites.json place --sites examples/bodies/cube_sites.json --markers 5 \
    --random-trials 100 --threads 1 --min-distance-difference 0.01 --exhaustive-limit 0 \
    --out "$w/cube5.json" --json
  keep place/cube_sites.json "$w/cube5.json"
}

record_crb() {
  local f s d
  for f in examples/layouts/{docking_target,drone,satellite,surgical_tool}.json \
    examples/layouts/{mocap_rigid_body.csv,apriltag_cube.yaml} "${TOOLS[@]}" \
    examples/bodies/cube_sites.json; do
    s=$(stem "$f")
    d=$(crb_distance "$f")
    run "crb/$s" crb "$f" --distance "$d" --focal 900 --noise-px 0.3 --threads 1
    run "crb/$s.json" crb "$f" --distance "$d" --focal 900 --noise-px 0.3 --threads 1 --json
  done
  local cube=examples/layouts/apriltag_cube.yaml
  run crb/apriltag.direction crb "$cube" --distance 2 --focal 900 --noise-px 0.3 \
    --principal-point 320 240 --direction 0.3,0.5,0.8 --samples 2000 --threads 1 --json
  run crb/apriltag.sweep-distance crb "$cube" --distance 2 --focal 900 --noise-px 0.3 \
    --sweep-distance 1:4:4 --samples 2000 --threads 1
  run crb/apriltag.sweep-distance.json crb "$cube" --distance 2 --focal 900 --noise-px 0.3 \
    --sweep-distance 1:4:4 --samples 2000 --threads 1 --json
  run crb/apriltag.sweep-tags crb "$cube" --distance 2 --focal 900 --noise-px 0.3 --sweep-tags \
    --tags-per-side 1,2 --tag-fill 0.5,0.8 --samples 2000 --threads 1
  run crb/apriltag.sweep-tags.json crb "$cube" --distance 2 --focal 900 --noise-px 0.3 \
    --sweep-tags --tags-per-side 1,3 --tag-fill 0.6 --samples 2000 --threads 1 --json
  run crb/drone.seen-whole crb examples/layouts/drone.json --distance 2.5 --focal 900 \
    --noise-px 0.3 --seen-whole --samples 2000 --threads 1 --json
}

record_tre() {
  local mc=(--monte-carlo 1000 --seed 5 --threads 1)
  local f s
  for f in examples/tools/{ndi_like,five_marker,west_planar}.json; do
    s=$(stem "$f")
    run "tre/$s.fle-rms" tre "$f" --target 0,0,-150 --fle-rms 0.25
    run "tre/$s.fle-rms.json" tre "$f" --target 0,0,-150 --fle-rms 0.25 --json
    run "tre/$s.fle-sigma" tre "$f" --target 0,0,-150 --fle-sigma 0.0995,0.2985 \
      --direction 0.3,0,1 "${mc[@]}"
    run "tre/$s.fle-sigma.json" tre "$f" --target 0,0,-150 --fle-sigma 0.0995,0.2985 \
      --direction 0.3,0,1 "${mc[@]}" --json
  done
  run tre/passive4_150.ini tre examples/tools/passive4_150.ini --target 0,-150,0 \
    --target 20,-100,5 --fle-sigma 0.0995,0.2985 "${mc[@]}"
  run tre/passive4_150.ini.json tre examples/tools/passive4_150.ini --target 0,-150,0 \
    --target 20,-100,5 --fle-rms 0.3 --json
  run tre/surgical_tool.json tre examples/layouts/surgical_tool.json --target 0,0,-200 \
    --fle-rms 0.2 "${mc[@]}" --json
  run tre/mocap tre examples/layouts/mocap_rigid_body.csv --target 0,0,-0.3 --fle-rms 0.0005
}

record_ident() {
  local t=(examples/tools/ndi_like.json examples/tools/west_planar.json
    examples/tools/passive4_150.ini examples/tools/five_marker.json)
  run ident/tools ident "${t[@]}"
  run ident/tools.json ident "${t[@]}" --json
  run ident/tools.min-visible-4 ident "${t[@]}" --min-visible 4
  run ident/tools.min-visible-4.json ident "${t[@]}" --min-visible 4 --json
  run ident/ndi_like ident examples/tools/ndi_like.json
  run ident/layouts.json ident examples/layouts/surgical_tool.json \
    examples/layouts/mocap_rigid_body.csv examples/layouts/drone.json --json
}

record_simulate() {
  local w="$SCRATCH/simulate"
  mkdir -p "$w"
  local base=(--trials 40 --seed 11 --threads 1)
  local f s
  for f in "${LAYOUTS[@]}" "${TOOLS[@]}"; do
    s=$(stem "$f")
    run "simulate/$s" simulate "$f" "${base[@]}"
    run "simulate/$s.json" simulate "$f" "${base[@]}" --json
  done
  run simulate/drone.pinhole simulate examples/layouts/drone.json "${base[@]}" --camera pinhole \
    --noise-px 0.5 --range 8 --focal 900 --principal-point 320 240
  run simulate/drone.pinhole.json simulate examples/layouts/drone.json "${base[@]}" \
    --camera pinhole --noise-px 0.5 --range 8 --focal 900 --json
  run simulate/satellite.worst.json simulate examples/layouts/satellite.json "${base[@]}" \
    --viewpoint worst --noise-px 0.2 --noise uniform --json
  run simulate/apriltag.viewpoint.json simulate examples/layouts/apriltag_cube.yaml \
    "${base[@]}" --camera pinhole --viewpoint 0.3,0.5,0.8 --range 5 --focal 800 --noise-px 0.1 \
    --methods perspective,oi-svd --per-trial --json
  run simulate/mocap.snr simulate examples/layouts/mocap_rigid_body.csv "${base[@]}" \
    --snr-db 40 --offset 0.2 0.1 --seen-whole
  run simulate/triad.csv simulate examples/layouts/triad.json "${base[@]}" \
    --csv "$w/triad.csv" --quiet
  keep simulate/triad.csv "$w/triad.csv"
  run simulate/surgical.csv.json simulate examples/layouts/surgical_tool.json "${base[@]}" \
    --camera pinhole --range 6 --noise-px 0.3 --csv "$w/surgical.csv" --json
  keep simulate/surgical.csv.json "$w/surgical.csv"
  # Two shards and their merge (equal to the unsharded run).
  run simulate/drone.shard1 simulate examples/layouts/drone.json "${base[@]}" --shard 1/2 --json
  run simulate/drone.shard2 simulate examples/layouts/drone.json "${base[@]}" --shard 2/2 --json
  cp "$OUT/simulate/drone.shard1.out" "$w/shard1.json"
  cp "$OUT/simulate/drone.shard2.out" "$w/shard2.json"
  run simulate/drone.merge simulate --merge "$w/shard1.json" "$w/shard2.json"
  run simulate/drone.merge.json simulate --merge "$w/shard1.json" "$w/shard2.json" --json
}

record_layout() {
  local w="$SCRATCH/layout"
  mkdir -p "$w"
  run layout/board.chessboard layout board --type chessboard --rows 5 --cols 7 --square 0.03 \
    --out "$w/chessboard.json"
  keep layout/board.chessboard "$w/chessboard.json"
  run layout/board.charuco.json layout board --type charuco --rows 4 --cols 5 --square 0.04 \
    --marker 0.03 --out "$w/charuco.json" --json
  keep layout/board.charuco.json "$w/charuco.json"
  run layout/board.aprilgrid layout board --type aprilgrid --rows 3 --cols 4 --square 0.05 \
    --spacing 0.25 --out "$w/aprilgrid.json"
  keep layout/board.aprilgrid "$w/aprilgrid.json"
  run layout/board.aprilgrid.json layout board --type aprilgrid --rows 2 --cols 2 --square 0.08 \
    --out "$w/aprilgrid2.json" --json
  keep layout/board.aprilgrid.json "$w/aprilgrid2.json"
  local f s ext target id=150
  for f in "${LAYOUTS[@]}" "${TOOLS[@]}"; do
    s=$(stem "$f")
    for ext in json csv ini; do
      target="$w/$s.$ext"
      # An Atracsys file's stem ends with its geometry id.
      [[ $ext == ini ]] && target="$w/${s%.*}_geometry$((id += 1)).ini"
      run "layout/convert.$s.to-$ext" layout convert "$f" --out "$target"
      keep "layout/convert.$s.to-$ext" "$target"
    done
    run "layout/convert.$s.to-json.json" layout convert "$f" --out "$w/$s.j.json" --json
  done
  run layout/convert.apriltag.centres layout convert examples/layouts/apriltag_cube.yaml \
    --tag-points centres --out "$w/apriltag_centres.csv" --json
  keep layout/convert.apriltag.centres "$w/apriltag_centres.csv"
  # The analysis of a board (planar: the Necker pair among the swaps).
  run layout/board.chessboard.analyze analyze "$w/chessboard.json" --json
}

# Every experiment, --quick and single-threaded: CSVs, summary.md and summary.json; then its
# figures (plot --experiment) into the same directory.
record_experiment() {
  local w="$SCRATCH/experiment" name
  mkdir -p "$w"
  for name in mcinroy-orientation mcinroy-pose bound haralick-2d2d haralick-3d3d \
    haralick-two-view wu-points wu-snr; do
    run "experiment/$name" experiment "$name" --quick --seed 2 --threads 1 --out "$w/$name"
    run "plot/experiment.$name" plot --experiment "$name" --out "$w/$name" --size 500x400
    keep "experiment/$name" "$w/$name"
  done
  run experiment/bound.json experiment bound --quick --trials 5 --seed 4 --threads 1 \
    --layouts examples/layouts/drone.json examples/layouts/apriltag_cube.yaml \
    examples/layouts/mocap_rigid_body.csv --out "$w/bound-json" --json
  run plot/experiment.bound.json plot --experiment bound --out "$w/bound-json" --size 400x300 \
    --title "bound, three layouts" --json
  keep experiment/bound.json "$w/bound-json"
  run experiment/wu-snr.json experiment wu-snr --quick --trials 4 --seed 4 --threads 1 \
    --out "$w/wu-snr-json" --json
  keep experiment/wu-snr.json "$w/wu-snr-json"
}

# The layout figures of every example (the visibility maps for layouts with normals, the
# placement figure for a placed layout, the design figure with --design), and the CRB and TRE
# figure families.
record_plot() {
  local w="$SCRATCH/plot" f s
  mkdir -p "$w"
  for f in "${LAYOUTS[@]}" examples/tools/{ndi_like.json,passive4_150.ini}; do
    s=$(stem "$f")
    run "plot/$s" plot "$f" --out "$w/$s" --size 500x400
    keep "plot/$s" "$w/$s"
  done
  run plot/drone.json.json plot examples/layouts/drone.json --out "$w/drone-json" --size 400x300 \
    --threshold-deg 10 --title "drone" --json
  keep plot/drone.json.json "$w/drone-json"
  run plot/satellite.seen-whole plot examples/layouts/satellite.json --seen-whole \
    --only viewpoint_map,vectors --out "$w/satellite-whole" --size 400x300
  keep plot/satellite.seen-whole "$w/satellite-whole"
  run plot/drone.svg plot examples/layouts/drone.json --only error_surface,dropout \
    --format svg --out "$w/drone-svg"
  keep plot/drone.svg "$w/drone-svg"
  run plot/mocap.radial plot examples/layouts/mocap_rigid_body.csv --normals radial \
    --cone-deg 100 --only visibility --out "$w/mocap-radial" --size 400x300 --json
  keep plot/mocap.radial "$w/mocap-radial"
  # The placement figure: the layout place wrote (record_place ran first).
  run plot/placed-capsule plot "$SCRATCH/place/capsule4.json" --out "$w/placed" --size 500x400
  keep plot/placed-capsule "$w/placed"
  # The design figure: from design --json (record_design ran first).
  cp "$OUT/design/note3_four_vectors.json.out" "$w/note3-design.json"
  run plot/note3.design plot examples/layouts/note3_four_vectors.json \
    --design "$w/note3-design.json" --out "$w/note3-design" --size 500x400 --json
  keep plot/note3.design "$w/note3-design"
  cp "$OUT/design/drone.json.out" "$w/drone-design.json"
  run plot/drone.design plot examples/layouts/drone.json --design "$w/drone-design.json" \
    --only design --out "$w/drone-design" --size 400x300
  keep plot/drone.design "$w/drone-design"
  # CRB: crb_map and crb_sweep.
  run plot/crb.apriltag plot examples/layouts/apriltag_cube.yaml --crb --distance 2 --focal 900 \
    --noise-px 0.3 --samples 2000 --out "$w/crb-apriltag" --size 500x400
  keep plot/crb.apriltag "$w/crb-apriltag"
  run plot/crb.drone.json plot examples/layouts/drone.json --crb --distance 2.5 --focal 900 \
    --noise-px 0.3 --principal-point 320 240 --sweep-distance 1:4:3 --samples 2000 \
    --out "$w/crb-drone" --size 400x300 --json
  keep plot/crb.drone.json "$w/crb-drone"
  # TRE: tre_tip_axis, tre_polar and tre_map.
  run plot/tre.ndi_like plot examples/tools/ndi_like.json --tre --target 0,0,-150 \
    --fle-sigma 0.0995,0.2985 --out "$w/tre-ndi" --size 500x400
  keep plot/tre.ndi_like "$w/tre-ndi"
  run plot/tre.west_planar.json plot examples/tools/west_planar.json --tre --target 0,0,-150 \
    --target 10,0,-100 --fle-rms 0.25 --direction 0.3,0,1 --radius 120 --out "$w/tre-west" \
    --size 400x300 --json
  keep plot/tre.west_planar.json "$w/tre-west"
}

# Bad inputs: exit 2 and one line on stderr.
record_errors() {
  local w="$SCRATCH/bad"
  mkdir -p "$w"
  printf '{"name": "broken", "points": [[0, 0, 0], [1, 0, 0]' >"$w/truncated.json"
  printf '{"name": "two", "points": [[0, 0, 0], [1, 0, 0]]}\n' >"$w/two_points.json"
  printf '{"name": "nan", "points": [[0, 0, 0], [1, 0, 0], [0, "x", 0]]}\n' >"$w/string.json"
  printf 'name,x,y\na,0,0\n' >"$w/short.csv"
  : >"$w/existing.json"
  run errors/unknown-subcommand frob
  run errors/no-subcommand
  run errors/unknown-option analyze examples/layouts/triad.json --frobnicate
  run errors/missing-file analyze examples/layouts/no_such_layout.json
  run errors/truncated-json analyze "$w/truncated.json"
  run errors/two-points analyze "$w/two_points.json" --json
  run errors/string-coordinate weights "$w/string.json"
  run errors/short-csv analyze "$w/short.csv"
  run errors/orient-no-measured orient examples/correspondences/perspective_pose.json
  run errors/pose-bad-method pose examples/correspondences/affine_pose.json --method nope
  run errors/pose-haralick2d-focal pose examples/correspondences/affine_pose.json \
    --method haralick-2d --focal 100
  run errors/simulate-trials-0 simulate examples/layouts/triad.json --trials 0
  run errors/simulate-pinhole-vectors simulate examples/layouts/triad.json --camera pinhole
  run errors/crb-vectors crb examples/layouts/triad.json --distance 2 --focal 900 --noise-px 0.3
  run errors/crb-no-focal crb examples/layouts/drone.json --distance 2 --noise-px 0.3
  run errors/tre-no-target tre examples/tools/ndi_like.json --fle-rms 0.2
  run errors/tre-both-fle tre examples/tools/ndi_like.json --target 0,0,-150 --fle-rms 0.2 \
    --fle-sigma 0.1,0.3
  run errors/ident-vectors ident examples/layouts/triad.json
  run errors/ident-min-visible ident examples/tools/ndi_like.json --min-visible 2
  run errors/design-yaml design examples/layouts/drone.json --add 1 --write "$w/out.yaml"
  run errors/design-existing design examples/layouts/drone.json --add 1 \
    --write "$w/existing.json"
  run errors/place-no-out place examples/bodies/capsule.obj --markers 4
  run errors/place-too-many place --sites examples/bodies/cube_sites.json --markers 40 \
    --out "$w/never.json"
  run errors/layout-board-rows layout board --type chessboard --rows 1 --cols 5 --square 0.02 \
    --out "$w/board.json"
  run errors/layout-convert-ext layout convert examples/layouts/drone.json --out "$w/drone.yaml"
  run errors/experiment-unknown experiment nope --out "$w/exp"
  run errors/plot-experiment-missing plot --experiment bound --out "$w/no-such-dir"
  run errors/plot-crb-no-distance plot examples/layouts/drone.json --crb --focal 900 \
    --noise-px 0.3 --out "$w/figs"
  run errors/plot-bad-size plot examples/layouts/drone.json --size 5x5 --out "$w/figs"
  keep errors/leftovers "$w"
}

normalise() {
  python3 - "$OUT" "$SCRATCH" "$VANTAGE" "$REPO" <<'PY'
import os
import re
import sys

out, scratch, vantage, repo = sys.argv[1:5]
# Longest first, so that a path inside another is replaced whole.
paths = sorted([(scratch, "@SCRATCH@"), (out, "@OUT@"), (vantage, "@VANTAGE@"),
                (repo, "@REPO@")], key=lambda p: -len(p[0]))
NUMBER = r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
TIME = "@TIME@"


def value_span(text, start):
    """End of the JSON value that starts at text[start] (an object, an array or a scalar)."""
    if text[start] in "[{":
        depth = 0
        for i in range(start, len(text)):
            if text[i] in "[{":
                depth += 1
            elif text[i] in "]}":
                depth -= 1
                if depth == 0:
                    return i + 1
    m = re.compile(r"[^,\]}\n]*").match(text, start)
    return m.end()


def mask_json(text):
    # "time_us": {median, mean, p95, max, count} (simulate's per-solve wall-clock time) keeps its
    # count; "time_us": [...] (per-trial times) loses every number.
    pieces, pos = [], 0
    for m in re.finditer(r'"time_us":\s*', text):
        start = m.end()
        if start < pos:
            continue
        end = value_span(text, start)
        value = text[start:end]
        if value.startswith("{"):
            value = re.sub(r'("(?:median|mean|p95|max)":\s*)' + NUMBER, r'\1"' + TIME + '"', value)
        elif value.startswith("["):
            value = re.sub(NUMBER, '"' + TIME + '"', value)
        pieces.append(text[pos:start] + value)
        pos = end
    pieces.append(text[pos:])
    text = "".join(pieces)
    # experiment's run time and the median solve time of its cells.
    return re.sub(r'("(?:seconds|time_us_median)":\s*)' + NUMBER, r'\1"' + TIME + '"', text)


TIME_COLUMN = re.compile(r"(^|_)time(_|$)", re.I)


def mask_csv(text):
    lines = text.split("\n")
    if not lines or "," not in lines[0]:
        return text
    header = lines[0].split(",")
    cols = [i for i, name in enumerate(header) if TIME_COLUMN.search(name.strip())]
    if not cols:
        return text
    for k in range(1, len(lines)):
        cells = lines[k].split(",")
        if len(cells) != len(header):
            continue
        for i in cols:
            if cells[i] != "":
                cells[i] = TIME
        lines[k] = ",".join(cells)
    return "\n".join(lines)


def mask_tables(text):
    """Markdown tables: the cells under a header that names a time."""
    lines = text.split("\n")
    cols = None
    for k, line in enumerate(lines):
        if not line.lstrip().startswith("|"):
            cols = None
            continue
        cells = line.split("|")
        if cols is None:
            cols = [i for i, c in enumerate(cells) if re.search(r"\btime\b", c, re.I)]
            continue
        if re.fullmatch(r"[\s|:-]*", line):
            continue
        for i in cols:
            if i < len(cells) and re.search(r"\d", cells[i]):
                cells[i] = " " + TIME + " "
        lines[k] = "|".join(cells)
    return "\n".join(lines)


def mask_text(text):
    # simulate: "  time per solve (us)      median X  mean X  p95 X  max X"
    text = re.sub(r"^(\s*time per solve \(us\)\s*)(.*)$",
                  lambda m: m.group(1) + re.sub(r"\b(median|mean|p95|max) " + NUMBER,
                                                r"\1 " + TIME, m.group(2)),
                  text, flags=re.M)
    # experiment: "(0.123 s)" after the list of files written.
    return re.sub(r"^\(" + NUMBER + r" s\)$", "(" + TIME + " s)", text, flags=re.M)


def normalise(path):
    name = os.path.basename(path)
    if name.endswith(".rc") or name == "images.sha256":
        return
    with open(path, "rb") as f:
        text = f.read().decode("utf-8", "surrogateescape")
    new = text
    for p, token in paths:
        new = new.replace(p, token)
    new = mask_json(new)
    if name.endswith(".csv"):
        new = mask_csv(new)
    new = mask_tables(new)
    new = mask_text(new)
    if new != text:
        with open(path, "wb") as f:
            f.write(new.encode("utf-8", "surrogateescape"))


for root, dirs, files in os.walk(out):
    dirs.sort()
    for name in sorted(files):
        normalise(os.path.join(root, name))
    # A figure that draws wall-clock times: its image hash is masked (its CSV stays, with the
    # time column masked).
    sums = os.path.join(root, "images.sha256")
    if os.path.isfile(sums):
        with open(sums) as f:
            lines = f.read().splitlines()
        lines = [(TIME + "  " + l.split("  ", 1)[1]) if l.endswith("_time.png") else l
                 for l in lines]
        with open(sums, "w") as f:
            f.write("\n".join(lines) + "\n")
PY
}

record() {
  [[ $# -eq 2 ]] || usage
  [[ -f $1 && -x $1 ]] || die "record: $1 is not an executable file"
  VANTAGE="$(cd "$(dirname "$1")" && pwd -P)/$(basename "$1")"
  OUT="$(realpath -m "$2")"
  if [[ -e $OUT ]]; then
    [[ -d $OUT ]] || die "record: $OUT exists and is not a directory"
    [[ -z "$(ls -A "$OUT")" ]] || die "record: $OUT is not empty (record into a new directory)"
  fi
  command -v python3 >/dev/null || die "record: python3 is needed (normalisation)"
  mkdir -p "$OUT" || die "record: cannot create $OUT"
  # Always in /tmp: a layout written there names its body mesh by a path relative to it, whose
  # "../" prefix depends on the scratch directory's depth.
  SCRATCH="$(mktemp -d /tmp/vantage-check-outputs.XXXXXX)" ||
    die "record: cannot create a scratch directory"
  trap 'rm -rf "$SCRATCH"' EXIT
  export LC_ALL=C TZ=UTC
  cd "$REPO" || die "record: cannot enter $REPO"
  LAYOUTS=(examples/layouts/*)
  TOOLS=(examples/tools/*)
  CORRESPONDENCES=(examples/correspondences/*)
  [[ -f ${LAYOUTS[0]} && -f ${TOOLS[0]} && -f ${CORRESPONDENCES[0]} ]] ||
    die "record: no examples under $REPO/examples"
  local started=$SECONDS part
  for part in help analyze weights orient pose design place crb tre ident simulate layout \
    experiment plot errors; do
    local t0=$SECONDS
    "record_$part"
    printf 'check-outputs.sh: %-10s %3d s\n' "$part" $((SECONDS - t0)) >&2
  done
  normalise || die "record: the normalisation failed"
  echo "check-outputs.sh: recorded $CALLS calls of $VANTAGE into $OUT in $((SECONDS - started)) s" >&2
}

# ---------------------------------------------------------------------------------------------
# compare

compare() {
  [[ $# -eq 2 ]] || usage
  [[ -d $1 ]] || die "compare: $1 is not a directory"
  [[ -d $2 ]] || die "compare: $2 is not a directory"
  local listing
  listing=$(diff -rq "$1" "$2")
  if [[ -z $listing ]]; then
    echo "check-outputs.sh: no difference ($(find "$1" -type f | wc -l) files)"
    return 0
  fi
  echo "check-outputs.sh: $(printf '%s\n' "$listing" | wc -l) files differ:"
  printf '%s\n' "$listing" | sed 's/^/  /'
  echo "(diff -r $1 $2 for the details)"
  return 1
}

case "${1:-}" in
record) shift && record "$@" ;;
compare) shift && compare "$@" ;;
*) usage ;;
esac
