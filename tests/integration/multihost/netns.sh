# Two "computers" on one machine: network namespaces joined by a veth pair, with addresses that
# exist only inside them. Source it, then:
#   netns_pair SUBNET   creates namespaces $tool and $surface, interfaces $tool_if (SUBNET.1) and
#                       $surface_if (SUBNET.2), multicast routed over the pair (DDS discovery);
#                       returns 77 where namespaces cannot be created (not root, no iproute2)
#   netns_chain SUBNET  the same two namespaces with a third, $middle, between them: $tool_if
#                       (SUBNET.1) <-veth-> $mid_tool_if | $middle | $mid_surface_if <-veth->
#                       $surface_if (SUBNET.2); nothing passes until a relay in $middle (the fault
#                       tests' plumb-test-linkem) forwards frames between $mid_tool_if and $mid_surface_if
#   netns_cleanup       stops what runs in them and deletes them (call it from the EXIT trap)
#   netns_exit_cleanup  the whole EXIT trap with lib.sh: the test's own programs, the namespaces, $work
netns_pair() {
  local subnet=$1
  if ! ip netns add plumb-probe-$$ 2>/dev/null; then
    echo "cannot create network namespaces here (needs root and iproute2): skipped"
    return 77
  fi
  ip netns del plumb-probe-$$
  tool=plumb-tool-$$ surface=plumb-surface-$$ tool_if=veth-t$$ surface_if=veth-s$$
  ip netns add "$tool" && ip netns add "$surface" || return 1
  ip link add "$tool_if" netns "$tool" type veth peer name "$surface_if" netns "$surface" || return 1
  ip -n "$tool" addr add "$subnet.1/24" dev "$tool_if"
  ip -n "$surface" addr add "$subnet.2/24" dev "$surface_if"
  for ns in "$tool" "$surface"; do ip -n "$ns" link set lo up; done
  ip -n "$tool" link set "$tool_if" up multicast on
  ip -n "$surface" link set "$surface_if" up multicast on
  # DDS discovery multicasts to 239.255.0.1: route multicast over the veth.
  ip -n "$tool" route add 224.0.0.0/4 dev "$tool_if"
  ip -n "$surface" route add 224.0.0.0/4 dev "$surface_if"
}
netns_chain() {
  local subnet=$1 ns
  if ! ip netns add plumb-probe-$$ 2>/dev/null; then
    echo "cannot create network namespaces here (needs root and iproute2): skipped"
    return 77
  fi
  ip netns del plumb-probe-$$
  tool=plumb-tool-$$ surface=plumb-surface-$$ middle=plumb-middle-$$
  tool_if=veth-t$$ surface_if=veth-s$$ mid_tool_if=veth-mt$$ mid_surface_if=veth-ms$$
  ip netns add "$tool" && ip netns add "$surface" && ip netns add "$middle" || return 1
  ip link add "$tool_if" netns "$tool" type veth peer name "$mid_tool_if" netns "$middle" || return 1
  ip link add "$surface_if" netns "$surface" type veth peer name "$mid_surface_if" netns "$middle" || return 1
  # The middle is a wire, not a host: no addresses, no IPv6 chatter of its own.
  ip netns exec "$middle" sysctl -qw net.ipv6.conf.all.disable_ipv6=1 net.ipv6.conf.default.disable_ipv6=1
  ip -n "$tool" addr add "$subnet.1/24" dev "$tool_if"
  ip -n "$surface" addr add "$subnet.2/24" dev "$surface_if"
  for ns in "$tool" "$surface" "$middle"; do ip -n "$ns" link set lo up; done
  ip -n "$middle" link set "$mid_tool_if" up
  ip -n "$middle" link set "$mid_surface_if" up
  ip -n "$tool" link set "$tool_if" up multicast on
  ip -n "$surface" link set "$surface_if" up multicast on
  ip -n "$tool" route add 224.0.0.0/4 dev "$tool_if"
  ip -n "$surface" route add 224.0.0.0/4 dev "$surface_if"
  # Fixed neighbour entries: across an outage ARP would fail and the sender's own kernel would drop
  # the datagrams to the other side before the wire, so that what the relay counts would no longer
  # be what the link lost.
  local tool_mac surface_mac
  tool_mac=$(ip -n "$tool" -o link show "$tool_if" | grep -o 'link/ether [0-9a-f:]*' | cut -d' ' -f2)
  surface_mac=$(ip -n "$surface" -o link show "$surface_if" | grep -o 'link/ether [0-9a-f:]*' | cut -d' ' -f2)
  ip -n "$tool" neigh replace "$subnet.2" lladdr "$surface_mac" dev "$tool_if" nud permanent
  ip -n "$surface" neigh replace "$subnet.1" lladdr "$tool_mac" dev "$surface_if" nud permanent
}
# The EXIT trap of a test on namespaces that keeps its programs in `pids` and its files in `$work`
# (lib.sh): stops them, deletes the namespaces (and what still runs in them), removes the folder.
netns_exit_cleanup() { stop_programs_and_remove_work; netns_cleanup; }
netns_cleanup() {
  local ns
  for ns in "${tool:-}" "${surface:-}" "${middle:-}"; do
    [ -n "$ns" ] || continue
    ip netns pids "$ns" 2>/dev/null | xargs -r kill 2>/dev/null
    ip netns del "$ns" 2>/dev/null
  done
}
