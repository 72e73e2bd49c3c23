#!/bin/bash
# jtracer-mpi across three "hosts" on one machine: three network namespaces on
# a bridge, one rank in each, talking TCP only; mpirun reaches the hosts through
# a launcher agent (ip netns exec) instead of ssh. Checks the CLI's bytes, the
# same bytes with one host slowed to about 1 Mbit/s, a killed rank and a pulled
# link: mid-frame, during the host's set-up, and in the middle of a big tile's
# transfer. Needs root (CAP_NET_ADMIN);
# skips (exit 77) where namespaces are refused.
# Usage: netns_test.sh JTRACER_CLI JTRACER_MPI MPIRUN SCENE
set -u
cli=$(realpath "$1") mpi=$(realpath "$2") mpirun=$(realpath "$3") scene=$(realpath "$4")

skip() { echo "SKIP: $*"; exit 77; }
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

[ "$(id -u)" = 0 ] || skip "network namespaces need root"
command -v ip > /dev/null || skip "iproute2 (ip) is not installed"

# Unique names, so that parallel runs do not collide (interface names <= 15 chars).
tag=jt$(printf '%05x' $(( ($$ ^ RANDOM) & 0xfffff )))
work=$(mktemp -d)
namespaces=()

cleanup() {
    for ns in "${namespaces[@]}"; do
        for pid in $(ip netns pids "$ns" 2> /dev/null); do kill -9 "$pid" 2> /dev/null; done
        ip netns del "$ns" 2> /dev/null
        rm -rf "/etc/netns/$ns"
    done
    for i in 1 2 3; do ip link del "${tag}v$i" 2> /dev/null; done
    ip link del "${tag}br" 2> /dev/null
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

ip link add "${tag}br" type bridge 2> /dev/null || skip "the kernel refuses to create a bridge (no CAP_NET_ADMIN?)"
ip link set "${tag}br" up
for i in 1 2 3; do
    ns=${tag}h$i
    ip netns add "$ns" 2> /dev/null || skip "the kernel refuses network namespaces"
    namespaces+=("$ns")
    ip link add "${tag}v$i" type veth peer name jtn netns "$ns" || skip "no veth pairs"
    ip link set "${tag}v$i" master "${tag}br" up
    ip -n "$ns" addr add "10.77.0.$i/24" dev jtn
    ip -n "$ns" link set jtn up
    ip -n "$ns" link set lo up
    # ip netns exec mounts these over /etc/hosts inside the namespace.
    mkdir -p "/etc/netns/$ns"
    printf '127.0.0.1 localhost\n10.77.0.1 h1\n10.77.0.2 h2\n10.77.0.3 h3\n' > "/etc/netns/$ns/hosts"
done

# mpirun calls `agent HOST COMMAND...` as it would call ssh; each host gets its
# own hostname (UTS namespace) so that messages name it.
cat > "$work/agent" << AGENT
#!/bin/sh
host=\$1; shift
exec ip netns exec "${tag}\$host" unshare --uts sh -c "hostname \$host && \$*"
AGENT
chmod +x "$work/agent"

export JT_MPI_TEST_ABORT_RANK=${JT_MPI_TEST_ABORT_RANK:-} JT_MPI_TEST_SLOW_SETUP_RANK=${JT_MPI_TEST_SLOW_SETUP_RANK:-} OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=detect_leaks=0
farm() {  # farm OUTPUT ARGS...: one rank a host, mpirun on h1
    local output=$1; shift
    (cd "$work" && timeout -k 5 100 ip netns exec "${tag}h1" unshare --uts sh -c 'hostname h1 && exec "$@"' sh \
        "$mpirun" --host h1,h2,h3 -np 3 --map-by node --bind-to none \
        --mca btl tcp,self --mca btl_tcp_if_include jtn --mca oob_tcp_if_include jtn \
        --mca plm_rsh_agent "$work/agent" --mca plm_rsh_no_tree_spawn 1 \
        -x JT_MPI_TEST_ABORT_RANK -x JT_MPI_TEST_SLOW_SETUP_RANK -x ASAN_OPTIONS \
        "$mpi" "$scene" -q -o "$output" "$@")
}
no_strays() {  # no process of ours may be left on the hosts still up (daemons take a moment)
    local host tries
    for host in "$@"; do
        for tries in $(seq 20); do
            [ -z "$(ip netns pids "${tag}$host")" ] && break
            sleep 0.5
        done
        [ -z "$(ip netns pids "${tag}$host")" ] || fail "processes left on $host after 10 s: $(ip netns pids "${tag}$host")"
    done
}
# After a lost host the other ranks may have rendered its tiles again and
# finished the frame before it was given up: an image is then complete and
# jtracer-cli's, never partial; no temporary file is ever left.
complete_or_nothing() {  # complete_or_nothing CASE OUTPUT REFERENCE SETTINGS...
    local what=$1 output=$2 reference=$3; shift 3
    if [ -e "$work/$output" ]; then
        [ -e "$work/$reference" ] || "$cli" "$scene" "$@" -q -o "$work/$reference" 2> /dev/null ||
            fail "jtracer-cli failed"
        cmp -s "$work/$reference" "$work/$output" && echo "(the frame was finished without it, and written)" ||
            fail "$what: a partial image was written"
    fi
    ls "$work" | grep -q "^$output." && fail "$what: a temporary file was left"
}
pulled_link_ended() {  # pulled_link_ended CASE LOG CODE SECONDS
    echo "exit $3 $4 s after the link went down: $(grep -o 'rank [0-9] on [a-z0-9]* stopped answering' "$2")"
    [ "$3" != 0 ] && [ "$3" != 124 ] || fail "$1: exit $3 (124: hung)"
    awk "BEGIN { exit !($4 < 30) }" || fail "$1: the run took $4 s to end"
    grep -q "rank 2 on h3 stopped answering" "$2" || fail "$1: no message naming rank 2 on h3: $(head -c 2000 "$2")"
}
pull_h3_link() {  # pull_h3_link CASE LOG: h3's link down, then the farm started last must end
    ip link set "${tag}v3" down
    local start code
    start=$(date +%s.%N)
    wait $farm_pid
    code=$?
    pulled_link_ended "$1" "$2" $code "$(awk "BEGIN { print $(date +%s.%N) - $start }")"
}
reconnect_h3() {  # h3 is unreachable while its link is down: its processes are ours to end
    ip netns pids "${tag}h3" | xargs -r kill -9
    ip link set "${tag}v3" up
    local tries  # until h1 answers h3 again (a closed port refuses at once)
    for tries in $(seq 30); do
        ip netns exec "${tag}h3" timeout 1 bash -c ': < /dev/tcp/10.77.0.1/9' 2>&1 | grep -q refused && break
        sleep 0.5
    done
    [ "$tries" = 1 ] || echo "(h1 answered h3 again after $tries tries)"
    [ "$tries" -lt 30 ] || fail "h1 does not answer h3 within 45 s of its link coming back"
}
slow_h3() {  # about 1 Mbit/s both ways
    tc qdisc add dev "${tag}v3" root tbf rate 1mbit burst 32kbit latency 400ms &&
        ip netns exec "${tag}h3" tc qdisc add dev jtn root tbf rate 1mbit burst 32kbit latency 400ms ||
        fail "tc tbf refused"
}
tile_counts() { grep -o 'rank [0-9]: [0-9]* tiles' "$1" | tr '\n' ' '; }

settings=(--width 240 --height 144 --samples 2)
"$cli" "$scene" "${settings[@]}" -q -o "$work/cli.bmp" 2> /dev/null || fail "jtracer-cli failed"

echo "== three hosts over TCP"
farm even.bmp "${settings[@]}" --tile-size 16 --stats 2> "$work/even.log" || fail "farm run failed: $(cat "$work/even.log")"
cmp -s "$work/cli.bmp" "$work/even.bmp" && echo "identical to jtracer-cli; $(tile_counts "$work/even.log")" ||
    fail "three hosts: bytes differ from jtracer-cli's"
no_strays h1 h2 h3

echo "== h3 slowed to 1 Mbit/s (tbf both ways)"
slow_h3
farm slow.bmp "${settings[@]}" --tile-size 16 --stats 2> "$work/slow.log" || fail "slowed run failed: $(cat "$work/slow.log")"
cmp -s "$work/cli.bmp" "$work/slow.bmp" && echo "identical to jtracer-cli; $(tile_counts "$work/slow.log")" ||
    fail "slowed host: bytes differ from jtracer-cli's"
no_strays h1 h2 h3
tc qdisc del dev "${tag}v3" root
ip netns exec "${tag}h3" tc qdisc del dev jtn root

echo "== rank 2 (h3) dies mid-frame"
start=$(date +%s.%N)
JT_MPI_TEST_ABORT_RANK=2 farm killed.bmp "${settings[@]}" --tile-size 16 2> "$work/killed.log"
code=$?
took=$(awk "BEGIN { print $(date +%s.%N) - $start }")
echo "exit $code after $took s"
[ "$code" != 0 ] && [ "$code" != 124 ] || fail "killed rank: exit $code (124: hung): $(cat "$work/killed.log")"
grep -q "rank 2" "$work/killed.log" || fail "killed rank: no message naming rank 2: $(cat "$work/killed.log")"
complete_or_nothing "killed rank" killed.bmp cli.bmp "${settings[@]}"
no_strays h1 h2 h3

# Mid-frame is an event, not a time: the link goes down once h3's tiles are
# flowing (rank 0 has taken 100 KB from it), however long a loaded machine
# takes to start the ranks and prepare the scene.
echo "== h3's link pulled mid-frame"
pulled_settings=(--width 1920 --height 1080 --samples 8)
received() { cat "/sys/class/net/${tag}v3/statistics/rx_bytes"; }
before=$(received)
farm pulled.bmp "${pulled_settings[@]}" --tile-size 32 2> "$work/pulled.log" &
farm_pid=$!
for tries in $(seq 900); do  # up to 90 s
    ip netns exec "${tag}h1" ss -tnp state established dst 10.77.0.3 | grep -q '"jtracer-mpi"' &&
        [ $(( $(received) - before )) -gt 100000 ] && break
    sleep 0.1
done
[ "$tries" -lt 900 ] || fail "pulled link: h3 sent no tiles within 90 s"
pull_h3_link "pulled link" "$work/pulled.log"
complete_or_nothing "pulled link" pulled.bmp cli-pulled.bmp "${pulled_settings[@]}"
no_strays h1 h2
reconnect_h3

# JT_MPI_TEST_SLOW_SETUP_RANK makes h3 prepare the scene for a minute longer
# than the others (saying meanwhile that it is alive); its link goes down once
# its hello has reached rank 0 (its connection to rank 0 is up), while rank 0
# waits for every host's set-up.
echo "== h3's link pulled during its set-up"
JT_MPI_TEST_SLOW_SETUP_RANK=2 farm setup.bmp "${settings[@]}" --tile-size 16 2> "$work/setup.log" &
farm_pid=$!
for tries in $(seq 300); do
    ip netns exec "${tag}h1" ss -tnp state established dst 10.77.0.3 | grep -q '"jtracer-mpi"' && break
    sleep 0.1
done
sleep 2
pull_h3_link "set-up" "$work/setup.log"
[ -e "$work/setup.bmp" ] && fail "set-up: an image was written before any tile was rendered"
ls "$work" | grep -q "^setup.bmp." && fail "set-up: a temporary file was left"
no_strays h1 h2
reconnect_h3

# A 512-pixel tile is 786 KB, over 6 s at 1 Mbit/s: the link goes down while
# rank 0 is taking in h3's first tile.
echo "== h3 slowed, its link pulled in the middle of a 786 KB tile"
slow_h3
big_settings=(--width 2048 --height 1024 --samples 1)
before=$(received)
farm big.bmp "${big_settings[@]}" --tile-size 512 2> "$work/big.log" &
farm_pid=$!
for tries in $(seq 600); do  # until 300 KB of h3's tile have left it
    [ $(( $(received) - before )) -gt 300000 ] && break
    sleep 0.1
done
sent=$(( $(received) - before ))
if [ "$sent" -le 300000 ]; then
    fail "big tile: h3 sent $(( sent / 1000 )) KB in 60 s, its tile never went on the wire"
    for host in h1 h2 h3; do  # what each host was doing
        echo "-- $host: $(ip netns exec "${tag}$host" ss -tn | grep -c ESTAB) TCP connections"
        for pid in $(ip netns pids "${tag}$host"); do ps -o pid=,stat=,etime=,args= -p "$pid" | cut -c1-160; done
    done
fi
echo "link down after $(( sent / 1000 )) KB from h3"
pull_h3_link "big tile" "$work/big.log"
complete_or_nothing "big tile" big.bmp cli-big.bmp "${big_settings[@]}"
no_strays h1 h2

[ "$failures" = 0 ] && echo "PASS" || { echo "$failures failure(s)"; exit 1; }
