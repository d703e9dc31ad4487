#!/usr/bin/env python3
"""Checks a PLC simulator against the independent reference (fatekref.py).

    python3 check_sim.py --sim /path/to/fatek-sim [--station N] [--profile m]
    python3 check_sim.py --sim "python3 tests/reference/fatekref.py serve"

The simulator is started with `--tcp 0 --udp 0 --station N --profile P` (or free ports picked here if
port 0 is refused); its ports are read from lines such as "listening on tcp 127.0.0.1:5000" or
"listening tcp 5000". Then every command of both protocols is sent over TCP and UDP and each answer
is compared with the literal expectation and with a reference PLC fed the same queries.
Last line: "N passed, M failed"; exit code 1 if anything failed.
"""

import argparse
import os
import queue
import re
import shlex
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import fatekref as F          # noqa: E402
import scenarios as S         # noqa: E402

START_TIMEOUT = 30.0      # generous: the build machine is shared and can be slow


class Sim:
    """One simulator process (started and stopped here, by its own pid)."""

    def __init__(self, command, extra):
        self.command, self.extra = command, extra
        self.proc = None
        self.lines = queue.Queue()
        self.output = []

    def start(self, tcp, udp):
        args = self.command + ["--tcp", str(tcp), "--udp", str(udp)] + self.extra
        try:
            self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True, errors="replace")
        except OSError as e:
            self.output.append("cannot start %s: %s" % (args, e))
            return None
        threading.Thread(target=self._pump, daemon=True).start()
        ports = {}
        deadline = time.monotonic() + START_TIMEOUT
        while len(ports) < 2 and time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=0.1)
            except queue.Empty:
                if self.proc.poll() is not None and self.lines.empty():
                    break
                continue
            low = line.lower()
            if "listen" not in low:
                continue
            numbers = re.findall(r"\d+", line)
            for kind in ("tcp", "udp"):
                if re.search(r"\b%s\b" % kind, low) and numbers:
                    ports[kind] = int(numbers[-1])
        if len(ports) < 2 or 0 in ports.values():
            self.stop()
            return None
        return ports

    def _pump(self):
        for line in self.proc.stdout:
            self.output.append(line.rstrip())
            self.lines.put(line)

    def stop(self):
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)


def start_sim(command, extra):
    sim = Sim(command, extra)
    ports = sim.start(0, 0)
    if ports is None:
        # Port 0 not accepted (or not reported): pick free ports here.
        sim = Sim(command, extra)
        ports = sim.start(S.free_port(), S.free_port(socket.SOCK_DGRAM))
    return sim, ports


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sim", required=True, help="simulator executable (or a command line)")
    ap.add_argument("--station", type=int, default=1)
    ap.add_argument("--profile", default="m")
    ap.add_argument("--sim-arg", action="append", default=[], help="extra argument for the simulator")
    ap.add_argument("--limit-check", default="fbs:R5000",
                    help="PROFILE:ADDR that the simulator must answer with error A ('' to skip)")
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args()

    command = shlex.split(args.sim)
    suite = S.Suite(args.verbose)

    extra = ["--station", str(args.station), "--profile", args.profile] + args.sim_arg
    sim, ports = start_sim(command, extra)
    if not suite.ok(ports is not None, "simulator starts and reports its tcp and udp ports",
                    "output:\n  " + "\n  ".join(sim.output[-20:])):
        return suite.summary()
    try:
        ref = F.RefPlc(args.station)
        for transport in ("tcp", "udp"):
            for protocol in ("facon", "binary"):
                S.live_scenario(suite, transport, ports[transport], protocol, args.station, "sim", ref)
    finally:
        sim.stop()

    if args.limit_check:
        profile, _, addr = args.limit_check.partition(":")
        addr = F.Address.parse(addr)
        extra = ["--station", str(args.station), "--profile", profile] + args.sim_arg
        sim, ports = start_sim(command, extra)
        if suite.ok(ports is not None, "simulator starts with --profile %s" % profile,
                    "output:\n  " + "\n  ".join(sim.output[-20:])):
            try:
                for transport in ("tcp", "udp"):
                    for protocol in ("facon", "binary"):
                        cl = F.Client(transport, "127.0.0.1", ports[transport], protocol, args.station, 2.0)
                        label = "sim(%s) %s %s" % (profile, transport, protocol)
                        try:
                            r = cl.read(F.Address(addr.el.symbol, 0), 1)
                            suite.ok(r.error == 0, "%s: read %s0 is fine" % (label, addr.el.symbol),
                                     repr(r.to_json()))
                            r = cl.read(addr, 1)
                            suite.ok(r.error == 0xA, "%s: read %s beyond the profile -> error A" % (label, addr),
                                     repr(r.to_json()))
                        except (OSError, TimeoutError, F.FatekError) as e:
                            suite.ok(False, label + ": limit check", str(e))
                        finally:
                            cl.close()
            finally:
                sim.stop()
    return suite.summary()


if __name__ == "__main__":
    sys.exit(main())
