#!/usr/bin/env bash
# Bad keystores: every check plumb makes before a vendor sees --security refuses with one line
# naming the file and the problem, exits non-zero, and never starts an unsecured participant.
# Each case is run through plumb-sim, plumb-estimator and `plumb topic echo` on the given vendor
# (they share components::connect) and through `plumb security check`.
# usage: bad_keystore.sh BIN_DIR TRANSPORT DOMAIN
set -uo pipefail
bin=$1 transport=$2
export PLUMB_DOMAIN_ID=$3 PLUMB_TRANSPORT=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../lib.sh"
start_work_with_programs
ks=$work/ks
"$bin/plumb" security create-keystore "$ks" --domains 10-19 > /dev/null || { fail "create-keystore"; finish; }
"$bin/plumb" security create-keystore "$work/other" --domains 10-19 > /dev/null || { fail "create-keystore other"; finish; }
"$bin/plumb" security create-identity "$work/other" plumb-sim > /dev/null || fail "other identity"
# new NAME [create-identity options]: a fresh identity with plumb-sim's permissions.
new() {
  local name=$1; shift
  "$bin/plumb" security create-identity "$ks" "$name" --no-permissions "$@" > /dev/null &&
    "$bin/plumb" security create-permissions "$ks" "$name" --publish 'plumb/*' --subscribe 'plumb/*' > /dev/null ||
    fail "making identity $name"
  echo "$ks/enclaves/$name"
}
# refused WHAT PATTERN DIR: every program refuses DIR with one line matching PATTERN.
refused() {
  local what=$1 pattern=$2 dir=$3
  expect_error "$what: plumb-sim" "$pattern" timeout 20 "$bin/plumb-sim" --security "$dir" --duration 1 --rate max
  expect_error "$what: plumb-estimator" "$pattern" timeout 20 "$bin/plumb-estimator" --security "$dir" --plugin compensated --count 1 --timeout 3
  expect_error "$what: plumb topic echo" "$pattern" timeout 20 "$bin/plumb" topic echo plumb/status --security "$dir" --timeout 3
  expect_error "$what: plumb security check" "$pattern" "$bin/plumb" security check "$dir"
}

good=$(new good)
"$bin/plumb" security check "$ks" good > /dev/null && pass "a good identity passes plumb security check" || fail "good identity refused"
timeout 20 "$bin/plumb" topic echo plumb/status --security "$good" --timeout 2 > /dev/null 2> "$work/good.err"
grep -q "^plumb: security" "$work/good.err" && fail "good identity refused: $(cat "$work/good.err")" ||
  pass "a good identity starts a secured participant on $transport"

dir=$(new expired --valid-from 20200101000000Z --valid-until 20210101000000Z)
refused "expired certificate" "security: .*/expired/cert.pem: certificate has expired" "$dir"
dir=$(new future --valid-from 20400101000000Z --valid-until 20410101000000Z)
refused "not-yet-valid certificate" "security: .*/future/cert.pem: certificate is not valid yet" "$dir"

dir=$(new tampered)
sed -i 's|<topic>plumb/\*</topic>|<topic>plumb/?</topic>|' "$dir/permissions.p7s"
grep -q "plumb/?" "$dir/permissions.p7s" || fail "the tampering did not change permissions.p7s"
refused "tampered permissions" "security: .*/tampered/permissions.p7s: signature does not verify" "$dir"

dir=$(new tampered-gov)
sed -i 's|<data_protection_kind>ENCRYPT<|<data_protection_kind>NONE<|' "$dir/governance.p7s"
refused "tampered governance" "security: .*/tampered-gov/governance.p7s: signature does not verify" "$dir"

dir=$(new open-key)
chmod 644 "$dir/key.pem"
refused "key readable by others" "security: .*/open-key/key.pem: private key is accessible by group or others \(mode 0644\)" "$dir"

dir=$(new writable)
chmod 666 "$dir/governance.p7s"
refused "governance writable by others" "security: .*/writable/governance.p7s: is writable by group or others" "$dir"

dir=$(new no-key)
rm "$dir/key.pem"
refused "missing private key" "security: .*/no-key/key.pem: private key is missing" "$dir"

dir=$(new locked-key)
openssl pkey -in "$dir/key.pem" -aes256 -passout pass:secret -out "$dir/key.enc" && mv "$dir/key.enc" "$dir/key.pem" &&
  chmod 600 "$dir/key.pem" || fail "encrypting a key"
refused "key with a passphrase (nobody to type it)" "security: .*/locked-key/key.pem: is not a PEM private key \(or is encrypted\)" "$dir"

# An identity of another CA dropped into this keystore's folder (its certificate and key).
dir=$(new foreign)
cp "$work/other/enclaves/plumb-sim/cert.pem" "$work/other/enclaves/plumb-sim/key.pem" "$dir/"
refused "certificate from another CA" "security: .*/foreign/cert.pem: certificate is not signed by .*identity_ca.cert.pem" "$dir"
# The other CA's identity folder is consistent in itself; the keystore check sees it is not ours.
expect_error "identity of another keystore" "is not this keystore's CA" "$bin/plumb" security check "$ks" ../../other/enclaves/plumb-sim

expect_error "--security on a missing folder" "security: .*/nowhere: is not a folder" \
  timeout 20 "$bin/plumb-sim" --security "$work/nowhere" --duration 1
PLUMB_SECURITY=$ks/enclaves/no-key expect_error "\$PLUMB_SECURITY is checked as --security is" "no-key/key.pem: private key is missing" \
  timeout 20 "$bin/plumb" topic echo plumb/status --timeout 3
# The keystore root given instead of an identity folder: said so, with the identities it holds.
refused "keystore root instead of an identity" "security: .*/ks: this is a keystore root: give --security .*/ks/enclaves/NAME \(found: .*good" "$ks"

# An unsecured listener beside a secured publisher sees nothing (discovery is encrypted): it says
# that the system may be secured and that --security is missing.
timeout 30 "$bin/plumb-sim" --security "$good" --duration 10 --rate-hz 100 --wait-subscribers 0 > "$work/secured_sim.log" 2>&1 &
pids+=($!)
timeout 20 "$bin/plumb" topic echo plumb/sensor/raw --timeout 4 > /dev/null 2> "$work/unsecured.err"
grep -q "nothing on plumb/sensor/raw for 3 s .*secured.*give --security DIR" "$work/unsecured.err" &&
  pass "an unsecured listener beside a secured system hints at --security" || fail "no --security hint: $(cat "$work/unsecured.err")"
expect_error "domain range above 230" "--domains: .*230" "$bin/plumb" security create-keystore "$work/ks2" --domains 0-232
finish
