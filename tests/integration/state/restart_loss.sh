#!/usr/bin/env bash
# plumb-estimator killed with -9 while plumb-sim streams at 100 Hz (batches of 32), started again
# 3 s later: the new instance reads its previous instance's record and reports the samples sent
# while it was down, on stderr and as lost_while_down on plumb/status, within one batch of what
# an independent watcher saw the sim send between the kill and the new instance's first batch.
# The sim runs on SIM's vendor, the host and the watcher on HOST's.
# usage: restart_loss.sh BIN_DIR SIM_TRANSPORT HOST_TRANSPORT DOMAIN
set -uo pipefail
bin=$1 s=$2 h=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
start_work_with_programs
cd "$work"
logs() { for f in "$work"/*.log; do echo "--- $f"; tail -n 8 "$f"; done; }
now() { date +%s.%N; }
host() {  # host LOG: the estimator host in the background, its pid in $host_pid
  "$bin/plumb-estimator" --transport "$h" --input plumb/sensor/raw --plugin integral --window 0.5 -q > "$1" 2>&1 &
  host_pid=$!
  pids+=($host_pid)
}

"$bin/plumb-test-faults-watch" --transport "$h" --sensor plumb/sensor/raw --batches > watch.log 2> watch_err.log &
pids+=($!)
host host1.log
"$bin/plumb-sim" --transport "$s" --rate-hz 100 --batch 32 --duration 60 --no-truth --wait-subscribers 20 > sim.log 2>&1 &
pids+=($!)
wait_for host1.log "tool 'sim' starts at sequence" 40 || { fail "the first host got no samples"; logs; finish; }
sleep 2
kill -9 $host_pid
t_kill=$(now)
record=$(ls state/plumb-estimator-domain"$PLUMB_DOMAIN_ID"-plumb_sensor_raw.resume 2>/dev/null)
[ -n "$record" ] && cp "$record" record_at_kill.txt || { fail "no record left by the first host: $(ls -R state)"; logs; finish; }
sleep 3
t_restart=$(now)
host host2.log
wait_for host2.log "were lost while this host was down" 30 || { fail "the new host reported no loss"; logs; finish; }
wait_for watch.log "^status [0-9.]+ plumb-estimator running .*lost_while_down=[1-9]" 15 ||
  fail "no lost_while_down on plumb/status: $(grep plumb-estimator watch.log | tail -1)"
kill -INT $host_pid
wait $host_pid
python3 - "$t_kill" "$t_restart" <<'PY' || fail "the counts disagree (above)"
import re, sys
t_kill, t_restart = float(sys.argv[1]), float(sys.argv[2])
batch = 32
previous_last = next(int(l.split()[0]) for l in open("record_at_kill.txt") if l.rstrip().endswith(" sim"))
log = open("host2.log").read()
new_first = int(re.search(r"tool 'sim' starts at sequence (\d+)", log).group(1))
first, last = map(int, re.search(r"samples (\d+)\.\.(\d+) of tool 'sim' were lost while this host was down", log).groups())
status = [l for l in open("watch.log") if re.match(r"status \S+ plumb-estimator running .*lost_while_down=[1-9]", l)]
on_status = int(re.search(r"lost_while_down=(\d+)", status[-1]).group(1))
batches = [tuple(map(float, l.split()[1:4])) for l in open("watch.log") if l.startswith("batch ")]
seen_at_kill = max(b[2] for b in batches if b[0] < t_kill)
# The watcher logs a batch when it takes it, up to 20 ms after it came: one it logged just after the
# kill may have reached the host before it.
while_down = [b for b in batches if t_kill + 0.5 < b[0] < t_restart]
sent_while_down = new_first - int(seen_at_kill) - 1
print(f"previous instance's last {previous_last}, new instance's first {new_first}; stderr {first}..{last}; "
      f"lost_while_down {on_status}; the watcher: last before the kill {int(seen_at_kill)}, so {sent_while_down} "
      f"sent while down; {len(while_down)} batches between the kill and the restart")
ok = True
def check(cond, what):
    global ok
    print(("ok   - " if cond else "FAIL - ") + what)
    ok = ok and cond
check(first == previous_last + 1 and last == new_first - 1, "the stderr line names the samples between the record and the first batch")
check(on_status == last - first + 1, f"plumb/status says {on_status}, the stderr line {last - first + 1}")
check(f", {on_status} lost while this host was down)" in log, "and so does the summary the host prints as it stops")
check(abs(on_status - sent_while_down) <= batch, f"{on_status} within one batch of the {sent_while_down} the sim sent while the host was down")
check(len(while_down) >= 2 and all(first <= b[1] and b[2] <= last for b in while_down),
      "every batch sent between the kill and the restart is among those counted")
sys.exit(0 if ok else 1)
PY
finish
