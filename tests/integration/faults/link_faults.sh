#!/usr/bin/env bash
# The link between the tool and the surface computer fails while data flows at 1 kHz. Three network
# namespaces: tool <-veth-> middle (plumb-test-linkem relays the frames) <-veth-> surface.
#   tool:    plumb-sim (1 kHz, best-effort sensor) and plumb-estimator (integral, 0.5 s windows:
#            reliable attitude that crosses the link)
#   surface: plumb-estimator (static, counts the best-effort samples lost), plumb-calibrate
#            (coefficients, transient-local), the watcher (attitude continuity, status). The surface
#            host is the only best-effort sensor reader across the link: each batch it misses is one
#            frame linkem dropped.
# Phase 1: the link down for 10 s: attitude resumes without restarts and none is lost, a reader
#          started on the tool side during the outage gets the calibration once the link is back.
# Phase 2: 20 % loss and 50 ms delay each way for 15 s: reliable attitude complete; the samples the
#          surface host counts as lost equal what linkem dropped (batches of 10 samples).
# At the end the tool side's interface goes down, and its components must still stop on SIGINT.
# usage: link_faults.sh BIN_DIR TOOL_TRANSPORT SURFACE_TRANSPORT DOMAIN
set -uo pipefail
bin=$1 tool_t=$2 surface_t=$3
export PLUMB_DOMAIN_ID=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
. "$here/../wait.sh"
. "$here/../multihost/netns.sh"
work=$(mktemp -d)
pids=()
trap netns_exit_cleanup EXIT
show_logs() { for f in "$work"/*.log; do echo "--- $f"; tail -n 15 "$f"; done; }
netns_chain 10.240.0 || { rc=$?; [ $rc -eq 77 ] && exit 77; fail "netns setup"; finish; }
now() { date +%s.%N; }
# stop PID: SIGINT, then SIGKILL if it is still there after 10 s (a hang is a failure).
stop() {
  kill -INT "$1" 2>/dev/null || return 0
  for ((i = 0; i < 100; ++i)); do kill -0 "$1" 2>/dev/null || { wait "$1" 2>/dev/null; return 0; }; sleep 0.1; done
  fail "pid $1 did not stop within 10 s of SIGINT"; kill -9 "$1"
}
# Arrays, not functions: a function started with & is a subshell, whose pid is not the program's.
in_tool=(ip netns exec "$tool")
in_surface=(ip netns exec "$surface")
batch=10

ip netns exec "$middle" "$bin/plumb-test-linkem" --a "$mid_tool_if" --b "$mid_surface_if" --big 1000 \
  --control "$work/link.ctl" --stats "$work/link.txt" > "$work/linkem.log" 2>&1 &
linkem=$!
pids+=($linkem)

# Coefficients to publish (the README's simulated board, calibrated on a simulated turntable).
printf 'format plumb-calibration 1\naccel.bias 0.05 -0.04 0.03\n' > "$work/board.txt"
(cd "$work" && "$bin/plumb-calibrate" --procedure 6pos --sim-truth board.txt --write-simulation acc_ > cal.log 2>&1) ||
  { fail "simulated calibration data"; show_logs; finish; }

"${in_surface[@]}" "$bin/plumb-test-faults-watch" --transport "$surface_t" --interface "$surface_if" \
  --attitude plumb/attitude/integral > "$work/watch.log" 2> "$work/watch_err.log" &
watch=$!
pids+=($watch)
"${in_surface[@]}" "$bin/plumb-estimator" --transport "$surface_t" --interface "$surface_if" --input plumb/sensor/raw \
  --plugin static --window 0.5 -q > "$work/surface_host.log" 2>&1 &
surface_host=$!
pids+=($surface_host)
"${in_surface[@]}" "$bin/plumb-calibrate" --transport "$surface_t" --interface "$surface_if" --procedure 6pos \
  --input "$work/acc_sensor.csv" --stations "$work/acc_stations.csv" --tool-id board --calibration-id link-test \
  --publish --linger 300 > "$work/calibrate.log" 2>&1 &
calibrate=$!
pids+=($calibrate)
"${in_tool[@]}" "$bin/plumb-estimator" --transport "$tool_t" --interface "$tool_if" --input plumb/sensor/raw \
  --plugin integral --window 0.5 -q > "$work/tool_host.log" 2>&1 &
tool_host=$!
pids+=($tool_host)
"${in_tool[@]}" "$bin/plumb-sim" --transport "$tool_t" --interface "$tool_if" --rate-hz 1000 --batch $batch --duration 300 \
  --inclination 5 --azimuth 45 --rpm 30 --no-truth --tool-id board --wait-subscribers 20 > "$work/sim.log" 2>&1 &
sim=$!
pids+=($sim)

# The kernel's UDP buffer errors in a namespace (RcvbufErrors + SndbufErrors): datagrams a loaded
# host dropped itself, on neither side of the link.
udp_buffer_errors() {
  ip netns exec "$1" awk '/^Udp:/ { if (!h) { for (i = 1; i <= NF; ++i) name[i] = $i; h = 1 }
    else for (i = 1; i <= NF; ++i) if (name[i] == "RcvbufErrors" || name[i] == "SndbufErrors") n += $i }
    END { print n + 0 }' /proc/net/snmp
}
host_drops_before=$(($(udp_buffer_errors "$tool") + $(udp_buffer_errors "$surface")))
wait_for "$work/watch.log" "^attitude " 40 || { fail "no attitude across the link"; show_logs; finish; }
wait_for "$work/watch.log" "^status .* plumb-estimator .*lost_samples" 20 || { fail "no estimator status"; show_logs; finish; }
sleep 3

# Phase 1: link down 10 s.
t_down=$(now)
kill -USR1 $linkem
sleep 1
"${in_tool[@]}" "$bin/plumb-test-faults-watch" --transport "$tool_t" --interface "$tool_if" --calibration \
  > "$work/tool_watch.log" 2> "$work/tool_watch_err.log" &
tool_watch=$!
pids+=($tool_watch)
sleep 9
t_up=$(now)
kill -USR2 $linkem
wait_for "$work/tool_watch.log" "^calibration .* link-test" 30 &&
  pass "a reader started on the tool side during the outage got the calibration after it" ||
  fail "no calibration on the tool side after the outage"
sleep 6

# Phase 2: 20 % loss, 50 ms delay.
printf 'loss=20\ndelay=50\n' > "$work/link.ctl"
kill -HUP $linkem
t_loss=$(now)
sleep 15
printf 'loss=0\ndelay=50\n' > "$work/link.ctl"
kill -HUP $linkem
t_loss_end=$(now)
sleep 4

for p in $sim $tool_host $surface_host $calibrate; do
  kill -0 $p 2>/dev/null || fail "a component ended during the faults (pid $p): $(show_logs)"
done
# Nothing hangs: the tool computer's interface goes down (a cable pulled, a switch port dead) and
# its components still stop on SIGINT (Cyclone DDS used to wait for ever for a datagram to itself).
sleep 2  # the last reliable attitude, status
ip -n "$tool" link set "$tool_if" down
n_fails=$fails
for p in $sim $tool_host $tool_watch; do stop $p; done
[ $fails -eq $n_fails ] && pass "the tool side stopped on SIGINT with its interface down"
for p in $surface_host $watch $calibrate $linkem; do stop $p; done
echo "linkem: $(tr '\n' ' ' < "$work/link.txt")"
host_drops=$(($(udp_buffer_errors "$tool") + $(udp_buffer_errors "$surface") - host_drops_before))
echo "UDP buffer errors on the two hosts during the run: $host_drops"

python3 "$here/check_faults.py" link "$work/watch.log" --linkem "$work/link.txt" --batch $batch --host-drops "$host_drops" \
  --down "$t_down" --up "$t_up" --loss "$t_loss" --loss-end "$t_loss_end" --window-ns 500000000 || { fails=$((fails + 1)); show_logs; }
finish
