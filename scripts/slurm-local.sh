#!/usr/bin/env sh
# A one-node Slurm cluster on this machine, for trying `vams sweep --slurm` and for the tests
# (tests/it/support/slurm.rs) that submit real job arrays.
#
#   eval "$(scripts/slurm-local.sh start)"   # prints `export SLURM_CONF=...` to eval
#   sbatch --array=0-3 --wrap 'echo $SLURM_ARRAY_TASK_ID'
#   scripts/slurm-local.sh status            # exit 0 when running, 1 when not
#   scripts/slurm-local.sh stop              # cancels the jobs, stops the daemons
#
# What `start` does: installs Debian's slurm-wlm and munge with apt-get when slurmctld, slurmd
# or munged is missing; writes a slurm.conf for one node (this host, `hostname -s`, with the CPU
# count and memory `slurmd -C` finds) in one default partition; starts a private munged, then
# slurmctld and slurmd (as the calling user: SlurmUser and SlurmdUser are whoever runs this,
# root in CI; root is needed only to install, and the jobs run as that user); waits up to
# 30 s for `sinfo` to show the node idle; prints the `export` lines for the client commands
# (sbatch, squeue, sinfo, scancel) on standard output, everything else on standard error.
# Starting a running cluster only prints the lines again.
#
# Times measured on the 2-core Debian 12 machine: install (apt-get update and the packages'
# download from scratch) and start 11.6 s, start alone 1-2 s, a 4-task array about 4 s from
# sbatch to the end, stop under 1 s (slurmctld saves its state; TERM to all three at once).
#
# Where its state lives: ${VAMS_SLURM_DIR:-${TMPDIR:-/tmp}/vams-slurm}, holding slurm.conf,
# cgroup.conf, munge/ (the key, socket, pid, log and seed of the private munged), state/
# (slurmctld's StateSaveLocation), spool/ (slurmd's), log/ and pid/. Nothing is written
# outside it but the packages apt-get installs; the system's munged, slurm.conf and services
# (which the Debian packages install but cannot start without systemd) are left alone.
# Ports: VAMS_SLURM_CTLD_PORT (default 6817) and VAMS_SLURM_SLURMD_PORT (default 6818); choose
# others to run beside a system Slurm or a second local cluster.
#
# `stop` cancels the cluster's jobs, ends the daemons it started (by their pid files, after
# checking each pid is still that daemon), then any of its job step daemons (slurmstepd
# processes whose environment names this cluster's slurm.conf), and leaves nothing running.
#
# Exit codes: 0 success; 1 the cluster did not start (the reason and the log's tail on
# standard error); 2 usage; 3 Slurm is missing and cannot be installed here (not root, no
# apt-get, or apt-get failed: no network); `status`: 1 when not running.
#
# Decisions, found on Debian 12 (slurm-wlm 22.05.8, munge 0.5.15) in a container whose pid 1
# is not systemd, with the cgroup v1/v2 hybrid mounted read-only to us:
# * Authentication by munge with a key of our own and a munged of our own: its socket under
#   the state directory, named in slurm.conf by `AuthInfo=socket=...`, which slurmctld, slurmd
#   and the client commands all read from SLURM_CONF, so SLURM_CONF is the only variable the
#   clients need. auth/none is not used: it trusts any uid a packet claims (anyone reaching
#   the port could run jobs as root) and it is gone from later Slurm releases; munge works
#   the same on every version. munged runs as root with --force (it refuses root otherwise).
# * No cgroups: ProctrackType=proctrack/linuxproc (process tree by parent pid),
#   TaskPlugin=task/none, JobAcctGatherType=jobacct_gather/none, so no cgroup plugin is loaded
#   at all and no cgroup.conf entry is needed; the cgroup.conf written (CgroupPlugin=disabled
#   is not known to 22.05) only keeps slurmd from reading /etc/slurm/cgroup.conf.
# * No accounting database (accounting_storage/none): `sacct` has nothing; wait on `squeue`.
# * SelectType=select/cons_tres with CR_CPU: each task takes one CPU, so as many tasks run at
#   once as the node has CPUs. ReturnToService=2: a node that was down comes back when slurmd
#   registers.
# * slurmd -N NAME, so the node finds its own entry whatever the resolver says of the host.
set -eu

die() {
    code="$1"
    shift
    echo "slurm-local: $*" >&2
    exit "$code"
}

dir="${VAMS_SLURM_DIR:-${TMPDIR:-/tmp}/vams-slurm}"
case "$dir" in
/*) ;;
*) dir="$(pwd)/$dir" ;;
esac
case "$dir" in
*[[:space:]\'\"#=]*) die 2 "the state directory $dir holds a space, quote, # or =, which slurm.conf cannot" ;;
esac
conf="$dir/slurm.conf"
ctld_port="${VAMS_SLURM_CTLD_PORT:-6817}"
slurmd_port="${VAMS_SLURM_SLURMD_PORT:-6818}"
host="$(hostname -s)"
SLURM_CONF="$conf"
export SLURM_CONF

# Installs slurm-wlm and munge when a daemon is missing; exit 3 when that cannot be done.
install_if_missing() {
    missing=""
    for cmd in slurmctld slurmd munged sbatch; do
        # Debian puts the daemons in /usr/sbin, which a non-root PATH may not have.
        if ! command -v "$cmd" >/dev/null 2>&1 && [ ! -x "/usr/sbin/$cmd" ]; then
            missing="$missing $cmd"
        fi
    done
    [ -z "$missing" ] && return 0
    if [ "$(id -u)" -ne 0 ]; then
        die 3 "missing$missing and not root: install slurm-wlm and munge (apt-get install slurm-wlm munge)"
    fi
    command -v apt-get >/dev/null 2>&1 || die 3 "missing$missing and no apt-get to install slurm-wlm and munge"
    echo "slurm-local: installing slurm-wlm and munge (missing$missing)" >&2
    export DEBIAN_FRONTEND=noninteractive
    # The packages' maintainer scripts try to start services; without systemd they only say so.
    if ! apt-get update -qq >"${TMPDIR:-/tmp}/vams-slurm-apt.log" 2>&1 ||
        ! apt-get install -y -qq --no-install-recommends slurm-wlm munge \
            >>"${TMPDIR:-/tmp}/vams-slurm-apt.log" 2>&1; then
        die 3 "apt-get could not install slurm-wlm and munge (no network?): see ${TMPDIR:-/tmp}/vams-slurm-apt.log"
    fi
}

PATH="$PATH:/usr/sbin:/sbin"
export PATH

# Whether the pid file $1 names a live process whose command line contains $2.
alive() {
    [ -s "$1" ] || return 1
    pid="$(cat "$1")"
    [ -r "/proc/$pid/cmdline" ] || return 1
    tr '\0' ' ' <"/proc/$pid/cmdline" | grep -q -- "$2"
}

running() {
    alive "$dir/munge/munged.pid" munged &&
        alive "$dir/pid/slurmctld.pid" slurmctld &&
        alive "$dir/pid/slurmd.pid" slurmd
}

print_exports() {
    # No quote to escape: the state directory holds none.
    echo "export SLURM_CONF='$conf'"
    echo "export VAMS_SLURM_DIR='$dir'"
}

write_conf() {
    # The node's CPUs, topology and memory as slurmd sees them: a node configured with more
    # than slurmd finds is drained ("Low socket*core*thread count", "Low RealMemory").
    # Addressed by 127.0.0.1: the host's name need not resolve (containers).
    node="$(slurmd -C | head -n 1 | sed "s/^NodeName=[^ ]*/NodeName=$host NodeAddr=127.0.0.1/")"
    user="$(id -un)"
    cat >"$conf" <<EOF
# Written by scripts/slurm-local.sh: a one-node cluster on this host, state under $dir.
ClusterName=vams-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/pid/slurmctld.pid
SlurmdPidFile=$dir/pid/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=60
MailProg=/bin/true
KillWait=5
$node State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
    printf '# Written by scripts/slurm-local.sh: no cgroup plugin is used.\n' >"$dir/cgroup.conf"
}

start_munged() {
    alive "$dir/munge/munged.pid" munged && return 0
    if [ ! -s "$dir/munge/munge.key" ]; then
        (umask 077 && head -c 1024 /dev/urandom >"$dir/munge/munge.key")
    fi
    rm -f "$dir/munge/munge.socket" "$dir/munge/munge.socket.lock"
    munged --force \
        --socket="$dir/munge/munge.socket" \
        --key-file="$dir/munge/munge.key" \
        --pid-file="$dir/munge/munged.pid" \
        --log-file="$dir/munge/munged.log" \
        --seed-file="$dir/munge/munged.seed" >>"$dir/log/start.log" 2>&1 ||
        fail "munged did not start" "$dir/munge/munged.log"
}

# Reports a failed start with the tail of the log $2, stops what did start, exits 1.
fail() {
    echo "slurm-local: $1; the end of $2:" >&2
    tail -n 15 "$2" >&2 2>/dev/null || true
    stop_all >/dev/null 2>&1 || true
    exit 1
}

start() {
    install_if_missing
    if running; then
        echo "slurm-local: already running ($dir)" >&2
        print_exports
        return 0
    fi
    mkdir -p "$dir"
    chmod 755 "$dir"
    mkdir -p "$dir/munge" "$dir/state" "$dir/spool" "$dir/log" "$dir/pid"
    chmod 700 "$dir/munge"
    write_conf
    start_munged
    if ! alive "$dir/pid/slurmctld.pid" slurmctld; then
        slurmctld -f "$conf" >>"$dir/log/start.log" 2>&1 ||
            fail "slurmctld did not start" "$dir/log/slurmctld.log"
    fi
    if ! alive "$dir/pid/slurmd.pid" slurmd; then
        slurmd -f "$conf" -N "$host" >>"$dir/log/start.log" 2>&1 ||
            fail "slurmd did not start" "$dir/log/slurmd.log"
    fi
    waited=0
    until [ "$(sinfo -h -N -n "$host" -o %t 2>/dev/null)" = idle ]; do
        if [ "$waited" -ge 30 ]; then
            fail "the node is not idle after 30 s (sinfo: $(sinfo -h -N -o '%t %E' 2>&1))" \
                "$dir/log/slurmd.log"
        fi
        sleep 1
        waited=$((waited + 1))
    done
    echo "slurm-local: running, node $host idle after ${waited} s ($dir)" >&2
    print_exports
}

# Sends TERM to the process in pid file $1 if it is still the daemon $2; prints its pid.
signal_daemon() {
    if alive "$1" "$2"; then
        pid="$(cat "$1")"
        kill "$pid" 2>/dev/null || true
        echo "$pid"
    fi
    rm -f "$1"
}

# Whether process $1 exists and is not a zombie (a daemon's parent is pid 1, which may not
# reap it: in a container it is not always an init).
live_pid() {
    [ -r "/proc/$1/stat" ] && [ "$(cut -d' ' -f3 "/proc/$1/stat" 2>/dev/null)" != Z ]
}

# Waits up to 10 s in all for the pids $@ to end, then kills what is left.
reap() {
    i=0
    for pid in "$@"; do
        while live_pid "$pid" && [ "$i" -lt 100 ]; do
            sleep 0.1
            i=$((i + 1))
        done
        if live_pid "$pid"; then
            kill -9 "$pid" 2>/dev/null || true
        fi
    done
}

# The job step daemons of this cluster: slurmstepd processes started by our slurmd, whose
# environment (inherited from it) names our slurm.conf.
our_stepds() {
    for p in /proc/[0-9]*; do
        [ -r "$p/environ" ] || continue
        case "$(cat "$p/comm" 2>/dev/null)" in
        slurmstepd) ;;
        *) continue ;;
        esac
        if tr '\0' '\n' <"$p/environ" 2>/dev/null | grep -qx "SLURM_CONF=$conf"; then
            echo "${p#/proc/}"
        fi
    done
}

stop_all() {
    if alive "$dir/pid/slurmctld.pid" slurmctld; then
        # Cancel every job so that no batch script outlives the cluster.
        jobs="$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')"
        if [ -n "${jobs% }" ]; then
            # shellcheck disable=SC2086 # the job ids are words
            scancel $jobs 2>/dev/null || true
            i=0
            while [ -n "$(squeue -h -t R,CG -o %A 2>/dev/null)" ] && [ "$i" -lt 20 ]; do
                sleep 0.5
                i=$((i + 1))
            done
        fi
    fi
    # All three at once: slurmctld takes a few seconds to save its state.
    pids="$(signal_daemon "$dir/pid/slurmd.pid" slurmd)
$(signal_daemon "$dir/pid/slurmctld.pid" slurmctld)
$(signal_daemon "$dir/munge/munged.pid" munged)"
    # shellcheck disable=SC2086 # the pids are words
    reap $pids
    left="$(our_stepds)"
    if [ -n "$left" ]; then
        # shellcheck disable=SC2086 # the pids are words
        kill -9 $left 2>/dev/null || true
    fi
    rm -f "$dir/munge/munge.socket" "$dir/munge/munge.socket.lock"
}

case "${1:-}" in
start) start ;;
stop)
    stop_all
    echo "slurm-local: stopped ($dir)" >&2
    ;;
status)
    if running; then
        echo "slurm-local: running ($dir)" >&2
        sinfo >&2 || true
    else
        echo "slurm-local: not running ($dir)" >&2
        exit 1
    fi
    ;;
*) die 2 "usage: $0 start|stop|status" ;;
esac
