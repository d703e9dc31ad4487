#!/usr/bin/env python3
"""Self-test of the reference implementation (fatekref.py):
every frame of tests/data/vectors.json (encode, parse, decode, server answer), then the reference client
against the reference server over real loopback TCP and UDP, every command, both protocols.
Last line: "N passed, M failed"; exit code 0 only if nothing failed."""

import contextlib
import io
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import fatekref as F          # noqa: E402
import scenarios as S         # noqa: E402


def unit_checks(suite):
    # Checksums of the reference's own examples.
    suite.ok(F.crc16_modbus(bytes([0x00, 0x02, 0x01, 0x40])) == 0x84A1, "CRC-16/MODBUS of 00 02 01 40 is A1 84")
    suite.ok(F.lrc(b"\x020140") == 0xC7, "LRC of STX 0140 is C7")
    # Address text widths.
    suite.ok(F.Address("X", 16).facon() == "X0016", "FACON discrete is 5 chars")
    suite.ok(F.Address("R", 12).facon() == "R00012" and F.Address("WY", 8).facon() == "WY0008"
             and F.Address("RT", 5).facon() == "RT0005", "FACON 16-bit register is 6 chars")
    suite.ok(F.Address("DR", 2).facon() == "DR00002" and F.Address("DWM", 0).facon() == "DWM0000"
             and F.Address("DRT", 4).facon() == "DRT0004", "FACON 32-bit register is 7 chars")
    # Binary parser: "D" + number 0x52xx begins like "DR": the payload length decides for 46.
    q = F.parse_binary_query(1, 0x46, bytes([1, 0x44, 0x52, 0x10]))
    suite.ok(str(q.addr) == "D21008" and q.count == 1, "binary 46 D21008 is not DR", repr(q))
    q = F.parse_binary_query(1, 0x46, bytes([1, 0x44, 0x52, 0x00, 0x10]))
    suite.ok(str(q.addr) == "DR16", "binary 46 DR16", repr(q))
    q = F.parse_binary_query(1, 0x47, bytes([1, 0x44, 0x52, 0x00, 0x00, 0x01]))
    suite.ok(str(q.addr) == "D20992" and q.values == [1], "binary 47 D20992 one word", repr(q))
    # Memory views: WY bit 0 = lowest point, DR = R(n+1):R(n).
    plc = F.RefPlc()
    plc.set(F.Address("WY", 8), 0x8001)
    suite.ok(plc.bits["Y"][8] == 1 and plc.bits["Y"][23] == 1 and sum(plc.bits["Y"]) == 2, "WY8 bit 0 is Y8")
    plc.set(F.Address("DR", 4), 0x12345678)
    suite.ok(plc.regs["R"][4] == 0x5678 and plc.regs["R"][5] == 0x1234, "DR4 = R5:R4")
    # Deframer: split frames, garbage, two frames in one chunk, bad checksum dropped.
    d = F.Deframer("auto", F.BIN_QUERY)
    good_b = F.binary_frame(0x51, bytes([1, 0x40]))
    good_f = F.facon_frame(1, 0x40, "")
    bad_f = good_f[:-2] + b"0\x03"
    out = d.feed(b"\xFFxx" + good_b[:5]) + d.feed(good_b[5:] + bad_f + good_f + good_b)
    suite.ok([p for p, _ in out] == ["binary", "facon", "binary"], "deframer splits and drops bad LRC", repr(out))


def run_cli(argv):
    """The client CLI in this process (a process per call would be slow on a loaded machine)."""
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        rc = F.main(argv)
    return rc, buf.getvalue()


def cli_checks(suite):
    """The client CLI against the server CLI (a separate process)."""
    here = os.path.dirname(os.path.abspath(__file__))
    script = os.path.join(here, "fatekref.py")
    srv = subprocess.Popen([sys.executable, script, "serve", "--station", "7"], stdout=subprocess.PIPE, text=True)
    try:
        ports = {}
        for _ in range(2):
            line = srv.stdout.readline().split()
            ports[line[1]] = int(line[2])
        for transport in ("tcp", "udp"):
            for protocol in ("facon", "binary"):
                base = ["client", "--%s" % transport, "127.0.0.1:%d" % ports[transport],
                        "--protocol", protocol, "--station", "7"]
                label = "CLI %s %s" % (transport, protocol)
                rc, out = run_cli(base + ["write", "DR10", "0x11223344"])
                suite.ok(rc == 0 and '"error": 0' in out, label + " write DR10", out)
                rc, out = run_cli(base + ["mread", "R10", "R11"])
                suite.ok(rc == 0 and '"values": [13124, 4386]' in out, label + " mread R10 R11", out)
                rc, out = run_cli(base + ["read", "WX9984"])
                suite.ok(rc == 0 and '"values": [0]' in out, label + " read WX9984", out)
                rc, out = run_cli(base + ["read", "WX9985"])
                suite.ok(rc == 1 and '"error": 10' in out, label + " read WX9985 -> error A", out)
                rc, out = run_cli(base[:-1] + ["9", "--timeout", "0.3", "status"])
                suite.ok(rc == 2 and "no answer" in out, label + " other station -> no answer", out)
    finally:
        srv.terminate()
        srv.wait(5)


def main():
    suite = S.Suite(verbose="-v" in sys.argv)
    unit_checks(suite)
    S.vector_tests(suite)
    server = F.BackgroundServer(F.RefPlc(3))
    try:
        ref = F.RefPlc(3)
        for transport, port in (("tcp", server.tcp_port), ("udp", server.udp_port)):
            for protocol in ("facon", "binary"):
                S.live_scenario(suite, transport, port, protocol, 3, "refserver", ref)
    finally:
        server.stop()
    cli_checks(suite)
    return suite.summary()


if __name__ == "__main__":
    sys.exit(main())
