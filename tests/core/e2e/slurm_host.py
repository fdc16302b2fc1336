"""A real Slurm on this one host, for a test, started and torn down by the test.

    from slurm_host import SlurmHost, unavailable
    why = unavailable()            # None, or why Slurm cannot run here
    with SlurmHost() as slurm:     # munged + slurmctld + slurmd, node idle
        out = slurm.run(["sbatch", "--parsable", "--wrap", "true"]).stdout
        states = slurm.wait([out.strip()])   # {"123": "COMPLETED"}

Everything lives in one temporary directory: a fresh munge key, munged with its
own socket, pid, log and seed files; a slurm.conf for one node (this host's
`hostname -s`, CPUs = nproc) with its state, spool, pid and log files, and its
own free TCP ports, so a Slurm already on the machine is neither used nor
disturbed. Root is not needed: every daemon runs as the user who runs the test
(SlurmUser = SlurmdUser = that user, munged with that user's key), and so do
the jobs (tried as root and as nobody). `SLURM_CONF` in `slurm.env` points
sbatch, squeue, sinfo and scontrol at this conf; no file outside the directory
is written.

What the experiments on Debian 12 (slurm-wlm 22.05, munge 0.5.15) showed:
  - munged refuses a socket whose directories are not searchable by all
    ("execute permissions for all required"): the temporary directory is made
    0755 (mkdtemp makes it 0700); the key is 0600, the user's own.
  - `AuthInfo=socket=PATH` points both the auth and the credential plugins
    (auth/munge, cred/munge) at that munged.
  - No cgroup: ProctrackType=proctrack/linuxproc, TaskPlugin=task/none.
    Accounting, job completion, switch and MPI are not named: their defaults
    are none already (checked: the same times without them), and a plugin name
    is one more thing another Slurm release may not know.
  - `--ready-timeout` worth of polling `sinfo -h -o %T` until the node says
    idle; the node first shows unknown / down* for a second or two.

The teardown (scancel every job still there, stop the daemons, then munged,
SIGKILL any job step of this Slurm left behind, remove the directory) runs
however the block ends; a daemon that does not end on SIGTERM within 10 s is
killed. On failure the daemons' logs are printed (`SlurmHost.logs()`).

Run by hand: python3 slurm_host.py   (starts, runs a 4-task array, prints times)
"""
import os
import pwd
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time


# Debian puts the daemons in /usr/sbin, which a user's PATH may lack.
for _d in ("/usr/sbin", "/sbin"):
    if _d not in os.environ.get("PATH", "").split(os.pathsep):
        os.environ["PATH"] = os.environ.get("PATH", "") + os.pathsep + _d


def _programs():
    """The programs a single-host Slurm needs, found on PATH (and /usr/sbin)."""
    return {
        "munged": shutil.which("munged"),        # munge
        "slurmctld": shutil.which("slurmctld"),  # slurmctld
        "slurmd": shutil.which("slurmd"),        # slurmd
        "sbatch": shutil.which("sbatch"),        # slurm-client, as the rest
        "sinfo": shutil.which("sinfo"),
        "scontrol": shutil.which("scontrol"),
        "squeue": shutil.which("squeue"),
        "scancel": shutil.which("scancel"),
    }


def unavailable():
    """None when a single-host Slurm can be started here, else why not."""
    missing = [n for n, p in _programs().items() if p is None]
    if missing:
        return ("not on PATH: " + ", ".join(missing) +
                " (Debian: apt-get install slurm-wlm munge; prime.sh's PACKAGES has them)")
    return None


def _find(name):
    return shutil.which(name) or name


def _free_ports(n):
    socks, ports = [], []
    for _ in range(n):
        s = socket.socket()
        s.bind(("127.0.0.1", 0))
        socks.append(s)
        ports.append(s.getsockname()[1])
    for s in socks:
        s.close()
    return ports


class SlurmError(RuntimeError):
    pass


class SlurmHost:
    def __init__(self, ready_timeout=60.0, keep=False):
        self.ready_timeout = ready_timeout
        self.keep = keep
        self.dir = None
        self.procs = {}
        self.env = None
        self.ready_seconds = None
        self.node = socket.gethostname().split(".")[0]
        self.user = pwd.getpwuid(os.geteuid()).pw_name

    # -- start ----------------------------------------------------------------
    def __enter__(self):
        why = unavailable()
        if why:
            raise SlurmError(why)
        try:
            self._start()
        except BaseException:
            try:
                self.logs(sys.stderr)
            finally:
                self.stop()
            raise
        return self

    def __exit__(self, kind, value, tb):
        try:
            if kind is not None:
                self.logs(sys.stderr)  # may fail too (a closed pipe): the teardown still runs
        finally:
            self.stop()
        return False

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def _start(self):
        t0 = time.monotonic()
        self.dir = tempfile.mkdtemp(prefix="prime-slurm-")
        os.chmod(self.dir, 0o755)  # munged: every directory above its socket searchable by all
        for d in ("munge", "state", "spool", "log", "run"):
            os.mkdir(self.path(d), 0o755)
        key = self.path("munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o600)
        self.munge_socket = self.path("munge", "munge.socket")
        munged = subprocess.run(
            [_find("munged"), "--socket=" + self.munge_socket, "--key-file=" + key,
             "--pid-file=" + self.path("munge", "munged.pid"),
             "--log-file=" + self.path("log", "munged.log"),
             "--seed-file=" + self.path("munge", "munged.seed")],
            capture_output=True, text=True)
        if munged.returncode != 0:
            raise SlurmError(f"munged failed (exit {munged.returncode}): {munged.stderr.strip()}")
        self.munged_pid = int(open(self.path("munge", "munged.pid")).read())
        ctld_port, slurmd_port = _free_ports(2)
        conf = self.path("slurm.conf")
        with open(conf, "w") as f:
            f.write(self._conf(ctld_port, slurmd_port))
        self.env = dict(os.environ, SLURM_CONF=conf)
        for name in ("slurmctld", "slurmd"):
            log = open(self.path("log", name + ".out"), "w")
            self.procs[name] = subprocess.Popen(
                [_find(name), "-D", "-f", conf], stdout=log, stderr=subprocess.STDOUT,
                env=self.env, start_new_session=True)
            log.close()
        self._wait_idle(t0)
        self.ready_seconds = time.monotonic() - t0

    def _conf(self, ctld_port, slurmd_port):
        p = self.path
        return f"""# A single-host Slurm for prime's tests (tests/core/e2e/slurm_host.py).
ClusterName=prime-test
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
SlurmUser={self.user}
SlurmdUser={self.user}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.munge_socket}
StateSaveLocation={p("state")}
SlurmdSpoolDir={p("spool")}
SlurmctldPidFile={p("run", "slurmctld.pid")}
SlurmdPidFile={p("run", "slurmd.pid")}
SlurmctldLogFile={p("log", "slurmctld.log")}
SlurmdLogFile={p("log", "slurmd.log")}
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=600
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
NodeName={self.node} NodeAddr=127.0.0.1 CPUs={os.cpu_count()} RealMemory=256 State=UNKNOWN
PartitionName=test Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
"""

    def _wait_idle(self, t0):
        state = ""
        while time.monotonic() - t0 < self.ready_timeout:
            for name, proc in self.procs.items():
                if proc.poll() is not None:
                    raise SlurmError(f"{name} exited {proc.returncode} while starting")
            r = self.run(["sinfo", "-h", "-N", "-o", "%T"])
            state = r.stdout.strip()
            if r.returncode == 0 and state in ("idle", "idle~"):
                return
            time.sleep(0.25)
        raise SlurmError(f"the node is not idle after {self.ready_timeout:.0f} s "
                         f"(sinfo says {state!r})")

    # -- use ------------------------------------------------------------------
    def run(self, args, **kw):
        """Runs a Slurm client (sbatch, squeue, ...) or any program with SLURM_CONF set."""
        args = list(args)
        found = _find(args[0])
        if found:
            args[0] = found
        kw.setdefault("capture_output", True)
        kw.setdefault("text", True)
        return subprocess.run(args, env=kw.pop("env", self.env), **kw)

    def job_states(self, job_ids):
        """{job id or array element id: STATE} from scontrol (no accounting here); a job
        whose dependency failed, pending for ever, is NEVER."""
        states = {}
        for job in job_ids:
            r = self.run(["scontrol", "-o", "show", "job", str(job)])
            for line in r.stdout.splitlines():
                fields = dict(w.split("=", 1) for w in line.split() if "=" in w)
                jid = fields.get("JobId", "?")
                if "ArrayTaskId" in fields:
                    jid = f"{fields.get('ArrayJobId', jid)}_{fields['ArrayTaskId']}"
                state = fields.get("JobState", "?")
                if state == "PENDING" and fields.get("Reason") == "DependencyNeverSatisfied":
                    state = "NEVER"  # its dependency failed: it will never run (final here)
                states[jid] = state
        return states

    def wait(self, job_ids, timeout=120.0):
        """Waits until no job of job_ids is pending or running; returns job_states()."""
        end = time.monotonic() + timeout
        live = ("PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "REQUEUED")
        while True:
            states = self.job_states(job_ids)
            if states and not any(s in live for s in states.values()):
                return states
            if time.monotonic() > end:
                raise SlurmError(f"jobs still live after {timeout:.0f} s: {states}")
            time.sleep(0.25)

    def logs(self, out):
        if not self.dir or not os.path.isdir(self.path("log")):
            return
        for name in sorted(os.listdir(self.path("log"))):
            text = open(self.path("log", name), errors="replace").read()
            tail = "\n".join(text.splitlines()[-25:])
            print(f"--- {name} (last 25 lines)\n{tail}", file=out)

    # -- stop -----------------------------------------------------------------
    def _cancel_jobs(self):
        """Cancels every job still queued or running, and waits (10 s at most) for the queue
        to empty, so that no job step outlives the daemons."""
        if self.env is None or any(p.poll() is not None for p in self.procs.values()) \
                or len(self.procs) < 2:
            return
        self.run(["scancel", "--user", self.user])
        end = time.monotonic() + 10
        while time.monotonic() < end:
            r = self.run(["squeue", "-h", "-o", "%i"])
            if r.returncode != 0 or not r.stdout.strip():
                return
            time.sleep(0.2)

    def _kill_strays(self):
        """SIGKILLs the job steps (slurmstepd, in sessions of their own) of this Slurm that
        are still there: the processes holding a file of its directory open."""
        if not self.dir:
            return
        for pid in os.listdir("/proc"):
            if not pid.isdigit() or int(pid) == os.getpid():
                continue
            try:
                if "slurmstepd" not in open(f"/proc/{pid}/cmdline", "rb").read().decode(
                        errors="replace"):
                    continue
                fds = os.listdir(f"/proc/{pid}/fd")
                mine = any(os.readlink(f"/proc/{pid}/fd/{fd}").startswith(self.dir + "/")
                           for fd in fds)
                if mine:
                    os.kill(int(pid), signal.SIGKILL)
            except OSError:
                continue

    def stop(self):
        try:
            self._cancel_jobs()
        except Exception as e:  # the teardown goes on whatever happens
            print(f"slurm_host: cancelling the jobs: {e}", file=sys.stderr)
        for name in ("slurmd", "slurmctld"):
            proc = self.procs.pop(name, None)
            if proc is None or proc.poll() is not None:
                continue
            proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
        pid = getattr(self, "munged_pid", None)
        if pid:
            self.munged_pid = None
            try:
                os.kill(pid, signal.SIGTERM)
                for _ in range(100):
                    os.kill(pid, 0)
                    time.sleep(0.1)
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self._kill_strays()
        if self.dir and not self.keep:
            shutil.rmtree(self.dir, ignore_errors=True)
            self.dir = None


def main():
    why = unavailable()
    if why:
        print("slurm_host: cannot run:", why)
        return 1
    with SlurmHost() as slurm:
        print(f"slurm_host: node {slurm.node} idle after {slurm.ready_seconds:.2f} s "
              f"({slurm.dir})")
        out = slurm.path("out")
        os.mkdir(out)
        t0 = time.monotonic()
        r = slurm.run(["sbatch", "--parsable", "--array=0-3", "-o", out + "/%A_%a.log",
                       "--wrap", "echo task $SLURM_ARRAY_TASK_ID on $(hostname -s)"],
                      cwd=out)
        if r.returncode != 0:
            print("slurm_host: sbatch failed:", r.stderr)
            return 1
        job = r.stdout.strip().split(";")[0]
        states = slurm.wait([job])
        print(f"slurm_host: 4-task array {job} done in {time.monotonic() - t0:.2f} s: "
              f"{sorted(states.items())}")
        for name in sorted(os.listdir(out)):
            print("  ", name, open(os.path.join(out, name)).read().strip())
        return 0 if all(s == "COMPLETED" for s in states.values()) and len(states) == 4 else 1


if __name__ == "__main__":
    sys.exit(main())
