"""Checks shared by selftest.py and check_sim.py.

Every query sent to the PLC under test is also run through a local reference RefPlc (through its wire
path: encode -> handle -> decode), and the answers are compared; most checks also state the expected
values literally (write, then read back), so they do not depend on the reference agreeing with itself.
"""

import json
import os
import socket

import fatekref as F
from fatekref import Address as A, Request as Q

HERE = os.path.dirname(os.path.abspath(__file__))
VECTORS = os.path.join(HERE, "..", "data", "vectors.json")

NO_ANSWER_WAIT = 0.25       # seconds we wait to be sure no answer comes


class Suite:
    def __init__(self, verbose=False):
        self.passed = self.failed = 0
        self.verbose = verbose
        self.failures = []

    def ok(self, cond, name, detail=""):
        if cond:
            self.passed += 1
            if self.verbose:
                print("PASS", name)
        else:
            self.failed += 1
            self.failures.append(name)
            print("FAIL %s %s" % (name, detail), flush=True)
        return cond

    def summary(self):
        print("%d passed, %d failed" % (self.passed, self.failed), flush=True)
        return 0 if self.failed == 0 else 1


def load_vectors():
    with open(VECTORS) as f:
        return json.load(f)


def vector_bytes(protocol, text):
    if protocol == "binary":
        return bytes.fromhex(text)
    return text.replace("<STX>", "\x02").replace("<ETX>", "\x03").encode("latin-1")


# ---------------------------------------------------------------------------------------------
# Vectors: typed query, expected decoded answer, memory to preload and memory expected afterwards
# ---------------------------------------------------------------------------------------------

def _status_plc(plc, run=False, rom=False, idset=False, ladder_error=False):
    plc.running, plc.rom_pack, plc.id_set, plc.ladder_checksum_error = run, rom, idset, ladder_error


def _typed_vectors():
    """(protocol, index) -> dict(req, values|status|data|error, pre(plc), post(plc) -> bool, server)."""
    Y = lambda n: A("Y", n)
    v = {}
    for p in ("binary", "facon"):
        pass
    b = "binary"
    v[(b, 0)] = dict(req=Q(0x40), status=bytes([0x29, 0, 0]),
                     pre=lambda plc: _status_plc(plc, run=True, rom=True, idset=True))
    v[(b, 1)] = dict(req=Q(0x40), status=bytes([0x01, 0, 0]), pre=lambda plc: _status_plc(plc, run=True))
    v[(b, 2)] = dict(req=Q(0x41, run=False), pre=lambda plc: _status_plc(plc, run=True),
                     post=lambda plc: not plc.running)
    v[(b, 3)] = dict(req=Q(0x41, run=True), post=lambda plc: plc.running)
    v[(b, 4)] = dict(req=Q(0x42, op=1, addr=A("X", 16)), post=lambda plc: plc.disabled["X"][16] == 1)
    v[(b, 5)] = dict(req=Q(0x43, addr=Y(10), count=7), values=[1, 0, 1, 0, 0, 0, 1])
    v[(b, 6)] = dict(req=Q(0x43, addr=A("X", 0), count=4), values=[1, 1, 1, 1])
    v[(b, 7)] = dict(req=Q(0x44, addr=A("X", 50), count=6), values=[0, 1, 0, 1, 1, 0])
    v[(b, 8)] = dict(req=Q(0x44, addr=Y(0), count=15), values=[0] * 15)
    v[(b, 9)] = dict(req=Q(0x45, addr=Y(0), values=[1, 0, 0, 1]))
    v[(b, 10)] = dict(req=Q(0x45, addr=Y(0), values=[0, 1, 0]))
    v[(b, 11)] = dict(req=Q(0x46, addr=A("R", 12), count=3), values=[0x10A5, 0x7FC4, 0x0001])
    v[(b, 12)] = dict(req=Q(0x46, addr=A("R", 0), count=2), values=[0xFF55, 0xFF4B])
    v[(b, 13)] = dict(req=Q(0x47, addr=A("WY", 16), values=[0xAAAA, 0x5555]))
    v[(b, 14)] = dict(req=Q(0x47, addr=A("R", 0), values=[0xFF55, 0xFF4B, 0xFF41]))
    v[(b, 15)] = dict(req=Q(0x48, addrs=[A("R", 1), Y(9), A("DWM", 0)]), values=[0x5C34, 1, 0x003547BA])
    v[(b, 16)] = dict(req=Q(0x48, addrs=[A("DR", 15), A("D", 1)]), values=[0x99990000, 0])
    v[(b, 17)] = dict(req=Q(0x49, items=[(Y(0), 1), (Y(1), 0), (A("WM", 8), 0x5555), (A("DR", 2), 0xFF)]))
    v[(b, 18)] = dict(req=Q(0x49, items=[(A("DR", 0), 0), (A("R", 15), 0xFF)]))
    v[(b, 19)] = dict(req=Q(0x4E, data=b"ABCDEFG"), data=b"ABCDEFG")
    v[(b, 20)] = dict(req=Q(0x4E, data=b"\xFF\xFF"), data=b"\xFF\xFF")
    v[(b, 21)] = dict(req=Q(0x46, addr=A("R", 0), count=1), error=0xA, limits={"R": -1})
    v[(b, 22)] = dict(req=Q(0x41, run=True), error=5, pre=lambda plc: _status_plc(plc, ladder_error=True),
                      post=lambda plc: not plc.running)
    f = "facon"
    v[(f, 0)] = dict(req=Q(0x40), status=bytes([0x29, 0, 0]),
                     pre=lambda plc: _status_plc(plc, run=True, rom=True, idset=True))
    v[(f, 1)] = dict(req=Q(0x41, run=True), post=lambda plc: plc.running)
    v[(f, 2)] = dict(req=Q(0x42, op=1, addr=A("X", 16)), post=lambda plc: plc.disabled["X"][16] == 1)
    v[(f, 3)] = dict(req=Q(0x43, addr=Y(10), count=7), values=[1, 0, 1, 0, 0, 0, 1])
    v[(f, 4)] = dict(req=Q(0x44, addr=A("X", 50), count=6), values=[0, 1, 0, 1, 1, 0])
    v[(f, 5)] = dict(req=Q(0x45, addr=Y(0), values=[1, 0, 0, 1]))
    v[(f, 6)] = dict(req=Q(0x46, addr=A("R", 12), count=3), values=[0x10A5, 0x7FC4, 0x0001])
    v[(f, 7)] = dict(req=Q(0x47, addr=A("WY", 8), values=[0xAAAA, 0x5555]))
    v[(f, 8)] = dict(req=Q(0x48, addrs=[A("R", 1), Y(9), A("DWM", 0)]), values=[0x5C34, 1, 0x003547BA])
    v[(f, 9)] = dict(req=Q(0x49, items=[(Y(0), 1), (Y(1), 0), (A("WM", 8), 0x5555), (A("DR", 2), 0xFF)]))
    v[(f, 10)] = dict(req=Q(0x4E, data=b"ABCDEFG"), data=b"ABCDEFG")
    v[(f, 11)] = dict(req=Q(0x46, addr=A("R", 0), count=1), error=0xA, limits={"R": -1})
    v[(f, 12)] = dict(req=Q(0x53), status=b"", server=False)   # the vector's answer is a placeholder
    return v


def _preload(plc, t):
    req = t["req"]
    if t.get("pre"):
        t["pre"](plc)
    if "values" in t and not t.get("error"):
        if req.cmd == 0x43:
            for i, x in enumerate(t["values"]):
                plc.disabled[req.addr.el.base][req.addr.number + i] = x
        elif req.cmd in (0x44, 0x46):
            for i, x in enumerate(t["values"]):
                plc.set(req.addr.advanced(i), x)
        elif req.cmd == 0x48:
            for a, x in zip(req.addrs, t["values"]):
                plc.set(a, x)


def _written(plc, req):
    """After a write vector, memory holds what was written."""
    if req.cmd in (0x45, 0x47):
        return [plc.get(req.addr.advanced(i)) for i in range(len(req.values))] == list(req.values)
    if req.cmd == 0x49:
        return all(plc.get(a) == x for a, x in req.items)
    return True


def vector_tests(suite):
    vectors = load_vectors()
    typed = _typed_vectors()
    for protocol in ("binary", "facon"):
        for i, vec in enumerate(vectors[protocol]):
            name = "vector %s[%d] %s" % (protocol, i, vec["what"][:50])
            t = typed.get((protocol, i))
            if not suite.ok(t is not None, name + ": typed form known"):
                continue
            try:
                _one_vector(suite, protocol, vec, t, name)
            except Exception as e:     # a broken implementation must give a failure, not a crash
                suite.ok(False, name, "exception %s: %s" % (type(e).__name__, e))


def _one_vector(suite, protocol, vec, t, name):
    query, response = vector_bytes(protocol, vec["query"]), vector_bytes(protocol, vec["response"])
    req = t["req"]
    req.station = 1
    # 1. typed query -> exact bytes
    enc = F.encode_query(protocol, req)
    suite.ok(enc == query, name + ": encode", "%r != %r" % (enc, query))
    # 2. bytes -> typed query (server parser)
    if protocol == "facon":
        st, cmd, text = F.unframe_facon(query)
        parsed = F.parse_facon_query(st, cmd, text)
    else:
        payload = F.unframe_binary(query, F.BIN_QUERY)
        parsed = F.parse_binary_query(payload[0], payload[1], payload[2:])
    suite.ok(repr(parsed) == repr(req), name + ": parse query", "%r != %r" % (parsed, req))
    # 3. answer bytes -> expected values
    resp = F.decode_response(protocol, response, req)
    exp_err = t.get("error", None if req.cmd == 0x4E else 0)
    good = resp.error == exp_err
    if "values" in t and not t.get("error"):
        good = good and resp.values == t["values"]
    if "status" in t:
        good = good and resp.status == t["status"]
    if "data" in t:
        good = good and resp.data == t["data"]
    suite.ok(good, name + ": decode answer", repr(resp.to_json()))
    # 4. reference server, memory preloaded, answers exactly the vector's answer
    plc = F.RefPlc(1, t.get("limits"))
    _preload(plc, t)
    answer = plc.handle(protocol, query)
    if t.get("server", True):
        suite.ok(answer == response, name + ": server answer", "%r != %r" % (answer, response))
        suite.ok(("post" not in t or t["post"](plc)) and _written(plc, req), name + ": memory after")
    else:
        r = F.decode_response(protocol, answer, req)
        suite.ok(r.error == 0 and len(r.status) == 64, name + ": server 53 answer has 64 bytes")
    # 5. same query to station 2 (other station): no answer; as broadcast: executed, no answer
    other = F.RefPlc(2, t.get("limits"))
    suite.ok(other.handle(protocol, query) is None, name + ": other station silent")
    req.station = 0
    plc = F.RefPlc(1, t.get("limits"))
    _preload(plc, t)
    silent = plc.handle(protocol, F.encode_query(protocol, req)) is None
    req.station = 1
    suite.ok(silent and ("post" not in t or t["post"](plc)) and _written(plc, req), name + ": broadcast")


# ---------------------------------------------------------------------------------------------
# Live scenario against a PLC reachable over TCP/UDP (the reference server or the simulator)
# ---------------------------------------------------------------------------------------------

class Live:
    def __init__(self, suite, transport, port, protocol, station, label, ref, host="127.0.0.1"):
        self.suite, self.protocol, self.station = suite, protocol, station
        self.label = "%s %s %s" % (label, transport, protocol)
        self.client = F.Client(transport, host, port, protocol, station, timeout=2.0)
        self.ref = ref        # what the reference says; shared by all checks of one PLC under test

    def close(self):
        self.client.close()

    def _name(self, name):
        return "%s: %s" % (self.label, name)

    def q(self, name, req, values=None, errors=(0,), data=None, compare_ref=True, no_answer=False):
        """Sends a typed query; checks the answer against the expectation and the reference model.
        Returns the decoded response (or None)."""
        if req.station is None:
            req.station = self.station
        name = self._name(name)
        frame = F.encode_query(self.protocol, req)
        ref_answer = self.ref.handle(self.protocol, frame)
        silent = no_answer or req.station == 0 or req.station != self.station
        try:
            answer = self.client.send_raw(frame, timeout=NO_ANSWER_WAIT if silent else None)
        except OSError as e:
            self.suite.ok(False, name, "transport error %s" % e)
            return None
        if silent:
            self.suite.ok(answer is None and ref_answer is None, name + " (no answer)",
                          "got %r" % (answer,))
            return None
        if not self.suite.ok(answer is not None, name, "no answer"):
            return None
        try:
            resp = F.decode_response(self.protocol, answer, req)
        except F.FatekError as e:
            self.suite.ok(False, name, "undecodable answer %r: %s" % (answer, e))
            return None
        exp_errors = errors if req.cmd != 0x4E or errors != (0,) else (None,)
        good = resp.error in exp_errors and resp.station == self.station
        detail = "answer %s" % json.dumps(resp.to_json())
        if values is not None:
            good = good and resp.values == values
            detail += " expected values %s" % values
        if data is not None:
            good = good and resp.data == data
        if compare_ref and ref_answer is not None:
            ref = F.decode_response(self.protocol, ref_answer, req)
            same = (ref.error == resp.error and ref.values == resp.values and ref.data == resp.data)
            if resp.status is not None and ref.status is not None:
                same = same and len(resp.status) == len(ref.status) and \
                    (not ref.status or (resp.status[0] & 1) == (ref.status[0] & 1))
            if not same and resp.error in exp_errors and len(exp_errors) > 1:
                same = True      # the reference is silent on which of these codes; both accepted
            good = good and same
            detail += " reference %s" % json.dumps(ref.to_json())
        self.suite.ok(good, name, detail)
        return resp

    def raw(self, name, frame, errors=None, cmd=None):
        """Raw bytes; errors None -> no answer expected; else the error code must be in errors."""
        name = self._name(name)
        ref_answer = self.ref.handle(self.protocol, frame)
        try:
            answer = self.client.send_raw(frame, timeout=NO_ANSWER_WAIT if errors is None else None)
        except OSError as e:
            self.suite.ok(False, name, "transport error %s" % e)
            return
        if errors is None:
            self.suite.ok(answer is None and ref_answer is None, name + " (no answer)", "got %r" % (answer,))
            return
        err = _raw_error(self.protocol, answer)
        ref_err = _raw_error(self.protocol, ref_answer)
        self.suite.ok(err in errors and ref_err in errors, name,
                      "answer %r error %s, reference error %s, expected %s" % (answer, err, ref_err, errors))


def _raw_error(protocol, frame):
    if frame is None:
        return None
    if protocol == "facon":
        u = F.unframe_facon(frame)
        return int(u[2][0], 16) if u and u[2] else None
    p = F.unframe_binary(frame, F.BIN_RESPONSE)
    return p[2] if p and len(p) >= 3 else None


def _facon_raw(station, cmdtext, data, good_lrc=True):
    body = b"\x02" + ("%02X" % station).encode() + cmdtext.encode() + data.encode("latin-1")
    chk = F.lrc(body) if good_lrc else (F.lrc(body) + 1) & 0xFF
    return body + ("%02X" % chk).encode() + b"\x03"


def _binary_raw(payload, good_crc=True):
    frame = bytearray(F.binary_frame(F.BIN_QUERY, payload))
    if not good_crc:
        frame[-4] ^= 0xFF
    return bytes(frame)


def live_scenario(suite, transport, port, protocol, station, label, ref):
    """Every command of one protocol over one transport. ref: the RefPlc mirroring the PLC under test
    (same station, same history of queries)."""
    L = Live(suite, transport, port, protocol, station, label, ref)
    fac = protocol == "facon"
    try:
        # 4E loopback
        L.q("4E loopback text", Q(0x4E, data=b"ABCDEFG"), data=b"ABCDEFG")
        L.q("4E loopback empty", Q(0x4E, data=b""), data=b"")
        big = bytes(range(0x20, 0x7F)) * 3
        lb = big[:256] if fac else bytes(range(256))
        L.q("4E loopback 256", Q(0x4E, data=lb), data=lb)
        # 41 / 40 / 53 RUN-STOP and status bits
        L.q("41 STOP", Q(0x41, run=False))
        r = L.q("40 status after STOP", Q(0x40))
        suite.ok(r is not None and len(r.status) == 3 and (r.status[0] & 1) == 0, L._name("40 STATUS1 B0=0 after STOP"))
        L.q("41 RUN", Q(0x41, run=True))
        r = L.q("40 status after RUN", Q(0x40))
        suite.ok(r is not None and len(r.status) == 3 and (r.status[0] & 1) == 1, L._name("40 STATUS1 B0=1 after RUN"))
        r = L.q("53 detail status", Q(0x53))
        suite.ok(r is not None and r.status is not None and len(r.status) == 64 and (r.status[0] & 1) == 1,
                 L._name("53 answer 64 bytes, STATUS1 B0=1"))
        L.q("41 STOP again", Q(0x41, run=False))
        r = L.q("53 detail after STOP", Q(0x53))
        suite.ok(r is not None and r.status is not None and len(r.status) == 64 and (r.status[0] & 1) == 0,
                 L._name("53 STATUS1 B0=0 after STOP"))
        # 45 / 44 discretes
        bits = [1, 0, 1, 1, 0, 0, 1, 0, 1, 1]
        L.q("45 write Y0..Y9", Q(0x45, addr=A("Y", 0), values=bits))
        L.q("44 read Y0..Y9", Q(0x44, addr=A("Y", 0), count=10), values=bits)
        many = [(i * 7 + i // 5) % 3 % 2 for i in range(256)]
        L.q("45 write M0..M255 (N=256)", Q(0x45, addr=A("M", 0), values=many))
        L.q("44 read M0..M255 (N=256)", Q(0x44, addr=A("M", 0), count=256), values=many)
        for sym in "XSTC":
            L.q("45 write %s5..%s7" % (sym, sym), Q(0x45, addr=A(sym, 5), values=[1, 1, 0]))
            L.q("44 read %s4..%s8" % (sym, sym), Q(0x44, addr=A(sym, 4), count=5), values=[0, 1, 1, 0, 0])
        # 47 / 46 registers of every kind
        regs = [0x1234, 0xFFFF, 0x0000, 0x8001]
        for sym in ("R", "D", "RT", "RC") + (() if fac else ("F",)):
            L.q("47 write %s10.." % sym, Q(0x47, addr=A(sym, 10), values=regs))
            L.q("46 read %s10.." % sym, Q(0x46, addr=A(sym, 10), count=4), values=regs)
        for sym in ("DR", "DD", "DRT", "DRC") + (() if fac else ("DF",)):
            L.q("47 write %s20.." % sym, Q(0x47, addr=A(sym, 20), values=[0x12345678, 0xFFFF0001]))
            L.q("46 read %s20.." % sym, Q(0x46, addr=A(sym, 20), count=2), values=[0x12345678, 0xFFFF0001])
        L.q("46 DR20 = R21:R20 (R20 low word)", Q(0x46, addr=A("R", 20), count=4),
            values=[0x5678, 0x1234, 0x0001, 0xFFFF])
        L.q("47 write WY16, WY32", Q(0x47, addr=A("WY", 16), values=[0xAAAA, 0x5555]))
        L.q("46 read WY16, WY32", Q(0x46, addr=A("WY", 16), count=2), values=[0xAAAA, 0x5555])
        L.q("44 Y16..Y19 = bit 0.. of WY16", Q(0x44, addr=A("Y", 16), count=4), values=[0, 1, 0, 1])
        L.q("47 write DWM64", Q(0x47, addr=A("DWM", 64), values=[0x80000001]))
        L.q("48 M64, M65, M95", Q(0x48, addrs=[A("M", 64), A("M", 65), A("M", 95)]), values=[1, 0, 1])
        L.q("46 read WM64, WM80", Q(0x46, addr=A("WM", 64), count=2), values=[0x0001, 0x8000])
        L.q("46 64 words R0..R63", Q(0x46, addr=A("R", 0), count=64))
        L.q("46 32 double words DR0..", Q(0x46, addr=A("DR", 0), count=32))
        L.q("47 64 words D100..", Q(0x47, addr=A("D", 100), values=list(range(64))))
        L.q("46 64 words D100..", Q(0x46, addr=A("D", 100), count=64), values=list(range(64)))
        # 49 / 48 mixed
        items = [(A("Y", 30), 1), (A("R", 300), 0xBEEF), (A("DD", 400), 0xCAFEF00D), (A("WX", 32), 0x00FF)]
        L.q("49 mixed write", Q(0x49, items=items))
        L.q("48 mixed read", Q(0x48, addrs=[a for a, _ in items]), values=[x for _, x in items])
        L.q("48 mixed read 64 words (32 DR)", Q(0x48, addrs=[A("DR", 2 * i) for i in range(32)]))
        L.q("49 mixed write 32 words", Q(0x49, items=[(A("R", 500 + i), i) for i in range(32)]))
        L.q("48 read back R500..R531", Q(0x48, addrs=[A("R", 500 + i) for i in range(32)]), values=list(range(32)))
        # 42 / 43 forcing
        L.q("42 disable Y5", Q(0x42, op=1, addr=A("Y", 5)))
        L.q("43 Y0..Y7 disable flags", Q(0x43, addr=A("Y", 0), count=8), values=[0, 0, 0, 0, 0, 1, 0, 0])
        L.q("42 set Y5", Q(0x42, op=3, addr=A("Y", 5)))
        L.q("44 Y5 after set", Q(0x44, addr=A("Y", 5), count=1), values=[1])
        L.q("42 reset Y5", Q(0x42, op=4, addr=A("Y", 5)))
        L.q("44 Y5 after reset", Q(0x44, addr=A("Y", 5), count=1), values=[0])
        L.q("42 enable Y5", Q(0x42, op=2, addr=A("Y", 5)))
        L.q("43 Y5 enabled again", Q(0x43, addr=A("Y", 5), count=1), values=[0])
        L.q("42 set M1000", Q(0x42, op=3, addr=A("M", 1000)))
        L.q("44 M1000 after set", Q(0x44, addr=A("M", 1000), count=1), values=[1])
        # 4F / 50 program pages (FACON only), written in STOP
        if fac:
            L.q("41 STOP before program write", Q(0x41, run=False))
            words = [(0x0101 * i) & 0xFFFF for i in range(64)]
            L.q("50 write page 1", Q(0x50, page=1, values=words))
            L.q("4F read page 1", Q(0x4F, page=1), values=words)
            r = L.q("4F read page 0 (header)", Q(0x4F, page=0), compare_ref=False)
            suite.ok(r is not None and r.values is not None and len(r.values) == 64, L._name("4F page has 64 words"))
            L.q("4F page FFFF beyond program", Q(0x4F, page=0xFFFF), errors=(0xA, 4))
        else:
            L.raw("4F not in binary protocol", _binary_raw(bytes([station, 0x4F, 0x00, 0x01])), errors=(4,))
        # error A: out of range or misaligned (beyond the largest model, so any profile agrees)
        L.q("46 WX3 misaligned", Q(0x46, addr=A("WX", 3), count=1), errors=(0xA,))
        L.q("47 DWY4 misaligned", Q(0x47, addr=A("DWY", 4), values=[1]), errors=(0xA,))
        L.q("46 DR65535 (needs R65536)", Q(0x46, addr=A("DR", 65535), count=1), errors=(0xA,))
        L.q("46 R65535 x2 crosses the end", Q(0x46, addr=A("R", 65535), count=2), errors=(0xA,))
        L.q("44 X9995 x10 crosses the end", Q(0x44, addr=A("X", 9995), count=10), errors=(0xA,))
        L.q("48 WY9992 beyond Y9999", Q(0x48, addrs=[A("WY", 9992)]), errors=(0xA,))
        L.q("49 with one bad element", Q(0x49, items=[(A("R", 700), 0x7777), (A("WM", 3), 1)]), errors=(0xA,))
        L.q("46 R700 unchanged by refused 49", Q(0x46, addr=A("R", 700), count=1), values=[0])
        if fac:
            L.raw("46 R99999 (5 digits, beyond R65535)", _facon_raw(station, "46", "01R99999"), errors=(0xA,))
            L.q("46 F10: F is a binary-protocol element", Q(0x46, addr=A("F", 10), count=1), errors=(0xA, 4))
            L.q("48 DF20: F is a binary-protocol element", Q(0x48, addrs=[A("DF", 20)]), errors=(0xA, 4))
        else:
            L.q("44 X10000", Q(0x44, addr=A("X", 10000), count=1), errors=(0xA,))
            L.q("42 Y10000", Q(0x42, op=3, addr=A("Y", 10000)), errors=(0xA,))
            L.q("46 RT10000", Q(0x46, addr=A("RT", 10000), count=1), errors=(0xA,))
        # error 4 (or 2 where the reference does not say which): malformed or over the limits
        L.raw("unknown command 4A", _facon_raw(station, "4A", "") if fac else _binary_raw(bytes([station, 0x4A])),
              errors=(4,))
        L.q("46 N=65 over the 64-word limit", Q(0x46, addr=A("R", 0), count=65), errors=(4, 2))
        L.q("46 N=33 of 32-bit registers", Q(0x46, addr=A("DR", 0), count=33), errors=(4, 2))
        L.q("48 65 words", Q(0x48, addrs=[A("R", i) for i in range(65)]), errors=(4, 2))
        L.q("49 33 words", Q(0x49, items=[(A("R", i), 0) for i in range(33)]), errors=(4, 2))
        if fac:
            L.raw("46 address too short", _facon_raw(station, "46", "01R001"), errors=(4,))
            L.raw("46 discrete element", _facon_raw(station, "46", "01X0000"), errors=(4, 0xA))
            L.raw("45 value 2 for a discrete", _facon_raw(station, "45", "01Y00002"), errors=(2, 4))
            L.raw("41 control 7", _facon_raw(station, "41", "7"), errors=(2, 4))
        else:
            L.raw("46 payload one byte short", _binary_raw(bytes([station, 0x46, 0x01, 0x52, 0x00])), errors=(4,))
            L.raw("46 discrete element", _binary_raw(bytes([station, 0x46, 0x01, 0x58, 0x00, 0x00])), errors=(4, 0xA))
            L.raw("45 value 2 for a discrete", _binary_raw(bytes([station, 0x45, 0x01, 0x59, 0x00, 0x00, 0x02])),
                  errors=(2, 4))
            L.raw("41 control 7", _binary_raw(bytes([station, 0x41, 0x07])), errors=(2, 4))
        # silence: bad checksum, other station, broadcast (executed, not answered)
        if fac:
            L.raw("bad LRC ignored", _facon_raw(station, "40", "", good_lrc=False))
        else:
            L.raw("bad CRC ignored", _binary_raw(bytes([station, 0x40]), good_crc=False))
        L.q("other station ignored", Q(0x47, station=(station % 254) + 1, addr=A("R", 800), values=[1]))
        L.q("broadcast write R801 (no answer)", Q(0x47, station=0, addr=A("R", 801), values=[0x4242]))
        L.q("R800 untouched, R801 written by broadcast", Q(0x46, addr=A("R", 800), count=2), values=[0, 0x4242])
        L.q("broadcast loopback (no answer)", Q(0x4E, station=0, data=b"HELLO"))
        L.q("link still fine after silences", Q(0x4E, data=b"OK"), data=b"OK")
        L.q("cleanup R801", Q(0x47, addr=A("R", 801), values=[0]))
    except Exception as e:     # a broken PLC or reference must give a failure, not a crash
        suite.ok(False, L.label + ": scenario aborted", "exception %s: %s" % (type(e).__name__, e))
    finally:
        L.close()
    return L


def free_port(kind=socket.SOCK_STREAM):
    s = socket.socket(socket.AF_INET, kind)
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port
