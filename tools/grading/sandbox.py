"""Where a student's code runs: every process the grade starts from a student's files (their
compile, their links, their test programs, their renders) goes through a Runner.

- Sandbox: Debian's bubblewrap (no IPC, its own PID namespace, so that every process the
  student's code starts ends with it; a network namespace of the student's own with nothing in
  it, not even a loopback that is up, made once per student with iproute2's `ip netns` and
  entered with util-linux's nsenter: a new one for every run would cost each run 80 ms; only the folders it is given, read-only, and
  one writable scratch folder), as a user id of the student's own (setpriv, from util-linux:
  no capability, and process counts per student), under prlimit's limits (memory, processes,
  CPU time, file size, open files, no core files), and in a control group of the student's
  own (cgroup-tools), so that all their processes together have at most the memory and the
  processes of the limits and an equal share of the CPU however many they start: a student who
  forks without end slows no one else. The scratch folder is a tmpfs of a fixed size, so a
  student cannot fill the machine's disk. It needs root (a user id, a group and a mount per
  student); without it, or without user namespaces, `Sandbox.check()` says why in one line.
- Plain: a student grading their own work (`./lab grade`): the same limits on file size and
  core files, a process group of its own, no isolation (it is their own machine).

Either way a process's output goes to a file, never to a pipe a child could hold open, and a
run that ends (or is stopped) leaves nothing running: the sandbox's PID namespace ends with
it; a plain run's process group is killed.
"""
import os
import shlex
import shutil
import signal
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

GIB = 1 << 30


@dataclass
class Limits:
    """What one student's processes may use (book §B.8 states the defaults)."""
    memory: int = 4 * GIB  # address space of each process, bytes
    processes: int = 256  # processes and threads of the student's user id at once
    cpu_seconds: int = 600  # CPU time of each process
    file_bytes: int = 256 << 20  # the largest file a process may write (an executable, an image, its output)
    scratch_bytes: int = 2 * GIB  # the whole scratch folder
    open_files: int = 256

    def prlimit(self, sandboxed):
        """prlimit's options: in the sandbox all of them; a plain run keeps the student's own
        memory and process limits (their machine), but never writes a core file or a huge file."""
        out = [f"--fsize={self.file_bytes}", "--core=0"]
        if sandboxed:
            out += [f"--as={self.memory}", f"--nproc={self.processes}", f"--cpu={self.cpu_seconds}",
                    f"--nofile={self.open_files}"]
        return out


class Process:
    """A started run: wait for it, or stop it and everything it started."""

    def __init__(self, popen, group):
        self.popen = popen
        self.group = group  # a plain run's process group

    def poll(self):
        return self.popen.poll()

    def wait(self):
        return self.popen.wait()

    def stop(self):
        """SIGKILL: the sandbox's namespace (bubblewrap's --die-with-parent takes its PID 1 with
        it), or the plain run's process group."""
        try:
            if self.group:
                os.killpg(self.popen.pid, signal.SIGKILL)
            else:
                self.popen.kill()
        except ProcessLookupError:
            pass
        self.popen.wait()

    def finish(self):
        """After the main process ended: a plain run's leftovers (children it forked) go too."""
        if self.group:
            try:
                os.killpg(self.popen.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def clean_environment(home):
    """The environment a student's process gets: nothing of the grader's."""
    return {"PATH": "/usr/bin:/bin", "HOME": str(home), "LANG": "C.UTF-8", "TMPDIR": "/tmp"}


class Plain:
    """No isolation: a student's own grade on their own machine."""
    sandboxed = False

    def __init__(self, scratch, limits=None):
        self.scratch = Path(scratch)
        self.limits = limits or Limits()

    def describe(self):
        return "no sandbox (your own code, on your own machine)"

    def start(self, argv, *, cwd, stdout, env=None, pass_fds=()):
        full = ["prlimit", *self.limits.prlimit(False), "--", *argv]
        environment = dict(os.environ)
        environment.update(env or {})
        with open(stdout, "wb") as out:
            popen = subprocess.Popen(full, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                     env=environment, pass_fds=pass_fds, start_new_session=True)
        return Process(popen, group=True)

    def open(self):
        self.scratch.mkdir(parents=True, exist_ok=True)

    def close(self):
        pass


class Group:
    """A student's processes as one control group (cgroup-tools' cgcreate, cgset, cgexec): the
    memory and process limits on all of them together, and the CPU shared equally between
    groups. cgroup v2 or v1, whichever the machine mounts; None when it can make none."""
    V2 = Path("/sys/fs/cgroup/cgroup.controllers").exists()
    # cgroup v1 keeps CPU time in a controller of its own.
    CONTROLLERS = "cpu,memory,pids" if V2 else "cpu,cpuacct,memory,pids"

    def __init__(self, name, limits):
        self.name, self.limits = name, limits

    def create(self):
        if not shutil.which("cgcreate"):
            return False
        if subprocess.run(["cgcreate", "-g", f"{self.CONTROLLERS}:{self.name}"], capture_output=True).returncode:
            return False
        memory = "memory.max" if self.V2 else "memory.limit_in_bytes"
        settings = ["-r", f"{memory}={self.limits.memory}", "-r", f"pids.max={self.limits.processes}"]
        if subprocess.run(["cgset", *settings, self.name], capture_output=True).returncode:
            self.delete()
            return False
        return True

    def prefix(self):
        return ["cgexec", "-g", f"{self.CONTROLLERS}:{self.name}"]

    def cpu_seconds(self):
        """The CPU time the group's processes have used, or None where it cannot be read."""
        try:
            if self.V2:
                stat = Path(f"/sys/fs/cgroup/{self.name}/cpu.stat").read_text()
                return int(stat.split("usage_usec")[1].split()[0]) / 1e6
            usage = next(Path("/sys/fs/cgroup").glob(f"*cpuacct*/{self.name}/cpuacct.usage"))
            return int(usage.read_text()) / 1e9
        except (OSError, IndexError, StopIteration, ValueError):
            return None

    def delete(self):
        subprocess.run(["cgdelete", "-r", f"{self.CONTROLLERS}:{self.name}"], capture_output=True)


class Sandbox:
    """bubblewrap as the student's own user id, in their own control group, on a scratch
    tmpfs of a fixed size. Several Sandbox objects may share one scratch folder (different
    read-only views of it): the first one opened mounts it and makes the group."""
    sandboxed = True

    def __init__(self, scratch, uid, read_only, limits=None):
        self.scratch = Path(scratch)
        self.uid = uid
        self.read_only = [Path(p) for p in read_only]
        self.limits = limits or Limits()
        self.mounted = False
        self.group = Group(f"rtlab/student-{uid}", self.limits)
        self.network = f"rtlab-student-{uid}"

    @staticmethod
    def check():
        """None when this machine can make the sandbox, else one line saying why not."""
        if os.geteuid() != 0:
            return ("the sandbox needs root (a user id and a size-limited scratch folder for each student): "
                    "run it with sudo, or give --no-sandbox for submissions you trust")
        for tool, package in (("bwrap", "bubblewrap"), ("setpriv", "util-linux"), ("prlimit", "util-linux"),
                              ("mount", "mount"), ("nsenter", "util-linux"), ("ip", "iproute2")):
            if not shutil.which(tool):
                return f"the sandbox needs {tool} (Debian package {package})"
        probe = subprocess.run(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--inh-caps=-all",
                                "bwrap", "--unshare-all", "--die-with-parent", *system_binds(), "--", "true"],
                               capture_output=True, text=True)
        if probe.returncode != 0:
            why = (probe.stderr.strip().splitlines() or ["no message"])[-1]
            return f"bubblewrap cannot make a sandbox on this machine ({why}): are user namespaces enabled?"
        return None

    def describe(self, grouped=True):
        mib = self.limits.memory >> 20
        whole = "in all" if grouped else "per process (no control group here)"
        return (f"sandbox: bubblewrap, user id {self.uid}, no network, {mib} MiB {whole}, "
                f"{self.limits.processes} processes, {self.limits.cpu_seconds} s of CPU per process, "
                f"scratch {self.limits.scratch_bytes >> 20} MiB")

    def open(self):
        """The scratch folder: a fresh tmpfs owned by the student's user id; their group."""
        self.grouped = self.group.create()
        subprocess.run(["ip", "netns", "delete", self.network], capture_output=True)  # a stopped run's
        subprocess.run(["ip", "netns", "add", self.network], check=True, capture_output=True)
        self.scratch.mkdir(parents=True, exist_ok=True)
        subprocess.run(["mount", "-t", "tmpfs", "-o",
                        f"size={self.limits.scratch_bytes},mode=0700,uid={self.uid},gid={self.uid},nosuid,nodev",
                        "rtlab-scratch", str(self.scratch)], check=True)
        self.mounted = True

    def close(self):
        """Everything in the scratch folder goes: read what you need from it first."""
        if self.mounted:
            subprocess.run(["umount", "--lazy", str(self.scratch)], check=False)
            self.mounted = False
        if getattr(self, "grouped", False):
            self.cpu = self.group.cpu_seconds()
            self.group.delete()
        subprocess.run(["ip", "netns", "delete", self.network], capture_output=True)
        try:
            self.scratch.rmdir()
        except OSError:
            pass

    def start(self, argv, *, cwd, stdout, env=None, pass_fds=()):
        grouped = self.group.prefix() if Path(f"/sys/fs/cgroup/pids/{self.group.name}").exists() or \
            Path(f"/sys/fs/cgroup/{self.group.name}").exists() else []
        full = [*grouped, "nsenter", f"--net=/run/netns/{self.network}",
                "setpriv", f"--reuid={self.uid}", f"--regid={self.uid}", "--clear-groups", "--inh-caps=-all",
                "prlimit", *self.limits.prlimit(True), "--",
                "bwrap", "--unshare-user", "--unshare-ipc", "--unshare-pid", "--unshare-uts", "--unshare-cgroup-try",
                "--die-with-parent", "--new-session", *system_binds(),
                "--proc", "/proc", "--dev", "/dev", "--size", str(64 << 20), "--tmpfs", "/tmp"]
        for path in self.read_only:
            full += ["--ro-bind", str(path), str(path)]
        full += ["--bind", str(self.scratch), str(self.scratch), "--chdir", str(cwd), "--", *argv]
        environment = clean_environment(self.scratch)
        environment.update(env or {})
        # The output file is the grader's, outside the sandbox: the student's process gets only
        # the descriptor, with RLIMIT_FSIZE on what it writes there.
        with open(stdout, "wb") as out:
            popen = subprocess.Popen(full, cwd="/", stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                     env=environment, pass_fds=pass_fds)
        return Process(popen, group=False)


def system_binds():
    """The system, read-only: /usr, /etc, and the merged-/usr links (or folders) beside them."""
    out = ["--ro-bind", "/usr", "/usr", "--ro-bind", "/etc", "/etc"]
    for name in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):
        path = Path("/") / name
        if path.is_symlink():
            out += ["--symlink", os.readlink(path), str(path)]
        elif path.is_dir():
            out += ["--ro-bind", str(path), str(path)]
    return out


@dataclass
class Outcome:
    """How a run ended."""
    code: int  # exit status, or -signal
    stopped: str = ""  # why the grader stopped it ("did not finish in 60 s"), else ""
    seconds: float = 0.0

    def describe(self):
        if self.stopped:
            return self.stopped
        if self.code < 0:
            try:
                return f"crashed ({signal.Signals(-self.code).name})"
            except ValueError:
                return f"killed by signal {-self.code}"
        if self.code >= 128 + 1 and self.code <= 128 + 64:  # a shell's way of saying a signal
            try:
                return f"crashed ({signal.Signals(self.code - 128).name})"
            except ValueError:
                pass
        return f"exit status {self.code}"


class Budget:
    """A student's time for all their programs' runs (a class's grade): once it is spent, what is
    left fails without running. None of it is spent before the first run."""

    def __init__(self, seconds):
        self.seconds, self.end = seconds, None

    def left(self):
        if self.end is None:
            self.end = time.monotonic() + self.seconds
        return self.end - time.monotonic()

    def reason(self):
        return f"not run to its end: your programs had used up the {self.seconds:.0f} s a student's runs may take"


def run(runner, argv, *, cwd, stdout, seconds, env=None, pass_fds=(), watch=None, budget=None):
    """Runs argv and waits at most `seconds` (and what is left of `budget`); `watch`, asked every
    50 ms, may return a reason to stop it early. Returns an Outcome."""
    limit, why = seconds, f"did not finish in {seconds:g} s"
    if budget is not None and budget.left() < limit:
        limit, why = budget.left(), budget.reason()
        if limit <= 0:
            Path(stdout).write_bytes(b"")
            return Outcome(code=-9, stopped=why)
    began = time.monotonic()
    process = runner.start(argv, cwd=cwd, stdout=stdout, env=env, pass_fds=pass_fds)
    stopped = ""
    while True:
        try:  # returns as soon as the process ends (Popen.wait polls from half a millisecond on)
            process.popen.wait(timeout=0.05)
            break
        except subprocess.TimeoutExpired:
            pass
        if time.monotonic() - began > limit:
            stopped = why
        elif watch:
            stopped = watch() or ""
        if stopped:
            process.stop()
            break
    code = process.wait()
    process.finish()
    return Outcome(code=code, stopped=stopped, seconds=time.monotonic() - began)


def run_batch(runner, commands, *, cwd, seconds_each, log):
    """Runs commands one after another in ONE start of the runner (a sandbox costs tens of
    milliseconds to start; a class's compiles and links are dozens of commands per student),
    each under coreutils' timeout. For steps that run none of the student's code (a compile, a
    link), whose statuses can be trusted. Returns an Outcome per command, and its output."""
    scratch = Path(runner.scratch)
    lines = [f"cd {shlex.quote(str(cwd))} || exit 1"]
    for k, argv in enumerate(commands):
        out = shlex.quote(str(scratch / f"batch-{k}.log"))
        lines.append(f"timeout -k 1 {seconds_each:g} {shlex.join(str(a) for a in argv)} >{out} 2>&1; "
                     f"echo $? >{shlex.quote(str(scratch / f'batch-{k}.status'))}")
    run(runner, ["/bin/sh", "-c", "\n".join(lines)], cwd=scratch, stdout=log,
        seconds=seconds_each * len(commands) + 10)
    results = []
    for k in range(len(commands)):
        status = scratch / f"batch-{k}.status"
        text = (scratch / f"batch-{k}.log").read_bytes()[:1 << 20].decode("utf-8", "replace") \
            if (scratch / f"batch-{k}.log").is_file() else ""
        try:
            code = int(status.read_text().strip())
        except (OSError, ValueError):
            code = -9
        stopped = f"did not finish in {seconds_each:g} s" if code in (124, 137) else ""
        results.append((Outcome(code=code, stopped=stopped), text))
        for done in (status, scratch / f"batch-{k}.log"):
            try:
                done.unlink()
            except OSError:
                pass
    return results
