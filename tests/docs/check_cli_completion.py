#!/usr/bin/env python3
"""fatek-cli's bash completion as a person uses it: a real interactive bash (bash -i) under a
pseudo-terminal, the script from `fatek-cli --completion bash` sourced, a command line typed and
TAB pressed; what the shell then shows on its line (one match: completed in place; several: listed
after a second TAB) is compared with what should be offered.

    check_cli_completion.py FATEK_CLI"""
import os
import pty
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time


class Shell:
    def __init__(self, cwd, env):
        self.pid, self.fd = pty.fork()
        if self.pid == 0:
            os.chdir(cwd)
            os.execvpe("bash", ["bash", "--norc", "--noprofile", "-i"], env)
        self.read(1.0)

    def read(self, quiet=0.5, limit=10.0):
        """What the terminal shows until it has been quiet for `quiet` seconds."""
        data = b""
        end = time.monotonic() + limit
        while time.monotonic() < end:
            ready, _, _ = select.select([self.fd], [], [], quiet)
            if not ready:
                break
            try:
                chunk = os.read(self.fd, 4096)
            except OSError:
                break
            if not chunk:
                break
            data += chunk
        return re.sub(r"\x1b\[[0-9;?]*[A-Za-z]|\x07|\r", "", data.decode("utf-8", "replace"))

    def type(self, text, quiet=0.5):
        os.write(self.fd, text.encode())
        return self.read(quiet)

    def close(self):
        os.kill(self.pid, signal.SIGKILL)  # the line typed is not to be run
        try:
            os.waitpid(self.pid, 0)
        except ChildProcessError:
            pass
        os.close(self.fd)


def main():
    cli = os.path.abspath(sys.argv[1])
    if not shutil.which("bash"):
        print("bash not found: skipped")
        return 0
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        bindir = os.path.join(scratch, "bin")
        os.mkdir(bindir)
        os.symlink(cli, os.path.join(bindir, "fatek-cli"))
        script = os.path.join(scratch, "fatek-cli.bash")
        with open(script, "w") as f:
            f.write(subprocess.run([cli, "--completion", "bash"], capture_output=True,
                                   text=True, check=True).stdout)
        links = os.path.join(scratch, "links.conf")
        with open(links, "w") as f:
            f.write("station1 = tcp://127.0.0.1:500\nstorage = udp://127.0.0.1:500\n"
                    "press = serial:///dev/ttyUSB0\n")
        work = os.path.join(scratch, "work")
        os.mkdir(work)
        for name in ("plan.csv", "resume.checkout.json"):
            open(os.path.join(work, name), "w").close()
        env = {"PATH": bindir + os.pathsep + os.environ.get("PATH", "/usr/bin:/bin"),
               "HOME": scratch, "TERM": "dumb", "FATEK_LINKS": links, "PS1": "$ ",
               "LANG": "C.UTF-8"}
        # (what is typed, TABs pressed, words the screen must show after it, words it must not)
        cases = [
            ("fatek-cli --link @sta", "\t", ["--link @station1"], []),
            ("fatek-cli --link @st", "\t\t", ["@station1", "@storage"], ["status", "stop"]),
            ("fatek-cli --link=@pr", "\t", ["--link=@press"], []),
            ("fatek-cli --link tc", "\t", ["--link tcp://"], []),
            ("fatek-cli --lang ", "\t\t", ["en", "zh_TW"], ["status"]),
            ("fatek-cli --lang z", "\t", ["--lang zh_TW"], []),
            ("fatek-cli --sim checkout pl", "\t", ["checkout plan.csv"], []),
            ("fatek-cli --sim checkout res", "\t", ["checkout resume.checkout.json"], []),
            ("fatek-cli --sim checkout X0 --report pl", "\t", ["--report plan.csv"], []),
            ("fatek-cli --sim checkout X0 --save res", "\t", ["--save resume.checkout.json"], []),
            ("fatek-cli --sim checkout X0 --punch pl", "\t", ["--punch plan.csv"], []),
            ("fatek-cli --sim checkout X0 --witness-c", "\t", ["--witness-company"], []),
            ("fatek-cli --sim mon", "\t", ["--sim monitor"], []),
            ("fatek-cli --sim monitor R0 --format as", "\t", ["--format ascii"], []),
        ]
        for typed, tabs, shown, hidden in cases:
            shell = Shell(work, env)
            try:
                shell.type(f"source {script}\n", 1.0)
                screen = shell.type(typed, 0.3)
                for tab in tabs:  # one at a time, as pressed
                    screen += shell.type(tab, 1.0)
            finally:
                shell.close()
            missing = [w for w in shown if w not in screen]
            extra = [w for w in hidden if re.search(rf"(^|\s){re.escape(w)}(\s|$)", screen)]
            if missing or extra:
                failures.append(f"{typed!r} + {len(tabs)} TAB: the screen shows {screen!r}; "
                                f"missing {missing}, unexpected {extra}")
    for f in failures:
        print("FAIL " + f)
    print(f"{len(cases)} completions typed, {len(failures)} wrong")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
