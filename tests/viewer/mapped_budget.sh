#!/usr/bin/env bash
# A volume over the viewer's memory budget (--memory-budget, here 0.01 GiB
# against a 64 MiB sparse float32 raw made by bench/make_sparse_volume.py):
# it opens mapped and unread with --iso, the start-up method is track, a seed
# grows the surface `isotrack extract --method track` gives from that point
# without asking; `all` waits for `confirm`, then yields the surfaces (count and
# triangles) of `isotrack extract --method all`; the summary says mapped.
# With the snap table track asks too. Without --iso the file is refused with
# a one-line message; under the budget
# `all` does not ask, so a `confirm` there is a script error. Snap states that
# do not fit the memory left are refused, naming the file.
#   mapped_budget.sh ISOTRACK VIEWER_CHECK OUT_DIR
set -euo pipefail
isotrack=$1 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
python=/usr/bin/python3
mkdir -p "$out"
cd "$out"
rm -f sparse.raw ./*.json ./*.err
balls=$("$python" "$here/../../bench/make_sparse_volume.py" sparse.raw 256 4)
read -r centre radius <<< "$(head -n 1 <<< "$balls")"
IFS=, read -r cx cy cz <<< "$centre"
seed="$((cx + radius)) $cy $cz"  # on the first ball's surface (iso 0.5 at its radius)
layout=(--volume sparse.raw --dims 256,256,256 --type float32 --iso 0.5)

sed "s/^track SEED$/track $seed/" "$here/mapped_budget.isotrack" > session.isotrack
"$isotrack" "${layout[@]}" --memory-budget 0.01 --script session.isotrack --size 960x600 --json > session.json
"$isotrack" extract "${layout[@]}" --method track --seed "${seed// /,}" --json > track.json
"$isotrack" extract "${layout[@]}" --method all --json > all.json

# Started on its own with `--method all`: it asks at once, before any surface.
printf 'wait\ncheckpoint asked\nconfirm\nwait\nquit\n' > asked.isotrack
"$isotrack" "${layout[@]}" --method all --memory-budget 0.01 --script asked.isotrack --size 960x600 --json > asked.json

"$python" - session.json track.json all.json asked.json <<'PY'
import json, sys
session, track, every, asked = (json.load(open(p)) for p in sys.argv[1:5])
point = {c["name"]: c for c in session["checkpoints"]}
def check(ok, what):
    if not ok:
        sys.exit("mapped_budget: " + what)
volume = session["volume"]
check(volume["mapped"] and volume["over_memory_budget"] and not volume["values_read"], f"volume {volume}")
check(volume["bytes"] == 256 ** 3 * 4 and volume["resident_bytes"] < volume["bytes"], f"volume {volume}")
check(session["default_isovalue"] is None, "a default isovalue was read")
check(point["start"]["method"] == "track" and point["start"]["surfaces"] == 0, f"start {point['start']}")
check(point["tracked"]["surfaces"] == 1 and point["tracked"]["confirm_bytes"] == 0, f"tracked {point['tracked']}")
check(point["asked"]["method"] == "all" and point["asked"]["confirm_bytes"] == volume["bytes"]
      and point["asked"]["surfaces"] == 1, f"asked {point['asked']}")
tracked = [s for s in session["surfaces"] if s["tracked"]]
cli_track = track["surfaces"][0]
check(len(tracked) == 1 and tracked[0]["triangles"] == cli_track["triangles"],
      f"tracked {[s['triangles'] for s in tracked]} vs extract's {cli_track['triangles']}")
mine = sorted(s["triangles"] for s in session["surfaces"])
theirs = sorted(s["triangles"] for s in every["surfaces"])
check(mine == theirs, f"all: {mine} vs extract's {theirs}")
check(asked["checkpoints"][0]["confirm_bytes"] == volume["bytes"] and asked["checkpoints"][0]["surfaces"] == 0,
      f"--method all did not ask first: {asked['checkpoints'][0]}")
check(sorted(s["triangles"] for s in asked["surfaces"]) == theirs, "--method all, confirmed: other surfaces")
print(f"tracked {cli_track['triangles']} triangles without asking; all asked for {volume['bytes']} bytes, "
      f"then {len(mine)} surfaces as extract; resident {volume['resident_bytes']} bytes")
PY

# With the snap table track asks too (its sample states cover the whole
# volume): nothing grows before `confirm`, then the surface of
# `isotrack extract --table snap --method track` from that point.
printf 'wait\ntrack %s\nwait\ncheckpoint asked\nconfirm\nwait\ncheckpoint tracked\nquit\n' "$seed" > snap.isotrack
"$isotrack" "${layout[@]}" --table snap --memory-budget 0.01 --script snap.isotrack --size 960x600 --json > snap.json
"$isotrack" extract "${layout[@]}" --table snap --method track --seed "${seed// /,}" --json > snap_track.json
"$python" - snap.json snap_track.json <<'PY'
import json, sys
session, track = (json.load(open(p)) for p in sys.argv[1:3])
point = {c["name"]: c for c in session["checkpoints"]}
bytes_ = session["volume"]["bytes"]
if point["asked"]["confirm_bytes"] != bytes_ or point["asked"]["surfaces"] != 0:
    sys.exit(f"mapped_budget: snap track did not ask first: {point['asked']}")
grown = [s["triangles"] for s in session["surfaces"] if s["tracked"]]
if grown != [track["surfaces"][0]["triangles"]]:
    sys.exit(f"mapped_budget: snap track grew {grown}, extract gives {track['surfaces'][0]['triangles']}")
print(f"snap track asked for {bytes_} bytes, then grew {grown[0]} triangles as extract")
PY

# No --iso over the budget: refused, naming the file, the budget and --iso.
printf 'wait\nquit\n' > idle.isotrack
if "$isotrack" --volume sparse.raw --dims 256,256,256 --type float32 --memory-budget 0.01 --script idle.isotrack \
    --size 960x600 2> noiso.err; then
    echo "mapped_budget: opened a volume over the budget without --iso" >&2
    exit 1
fi
grep -q "sparse.raw: .* over the memory budget of .*give --iso" noiso.err
[[ $(wc -l < noiso.err) -eq 1 ]]

# Under the budget nothing asks, so `confirm` finds nothing to confirm.
printf 'method all\nwait\nconfirm\nquit\n' > under.isotrack
if "$isotrack" "${layout[@]}" --script under.isotrack --size 960x600 2> under.err; then
    echo "mapped_budget: confirm succeeded under the budget" >&2
    exit 1
fi
grep -q "under.isotrack:3: confirm: no extraction waits for confirmation" under.err
echo "refused without --iso: $(cat noiso.err)"

# Confirmed, snap work that still does not fit the memory left (here an
# address-space limit beside a 1 GiB sparse file) is refused in one line that
# names the file, and the script stops there: a click's track (the viewer's own
# tracker) and `all` (the extraction worker).
balls=$("$python" "$here/../../bench/make_sparse_volume.py" big.raw 640 1)
read -r centre radius <<< "$balls"
IFS=, read -r cx cy cz <<< "$centre"
printf 'wait\ntrack %s %s %s\nwait\nconfirm\nwait\nquit\n' "$((cx + radius))" "$cy" "$cz" > tight.isotrack
printf 'wait\nmethod all\nwait\nconfirm\nwait\nquit\n' > tight_all.isotrack
for script in tight.isotrack:5 tight_all.isotrack:4; do
    if (ulimit -v 2000000 && exec "$isotrack" --volume big.raw --dims 640,640,640 --type float32 --iso 0.5 \
        --table snap --memory-budget 0.01 --script "${script%:*}" --size 960x600) > /dev/null 2> tight.err; then
        echo "mapped_budget: ${script%:*}: snap states over the memory left were accepted" >&2
        exit 1
    fi
    grep -q "^isotrack: $script: big.raw: the snap table's sample states, 3 bytes a sample: 640 x 640 x 640 \
samples need 750.0 MiB, more than the .* of memory available$" tight.err || { cat tight.err >&2; exit 1; }
    [[ $(wc -l < tight.err) -eq 1 ]]
    echo "refused under ulimit -v: $(cat tight.err)"
done
rm -f big.raw
