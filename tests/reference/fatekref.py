#!/usr/bin/env python3
"""Independent reference implementation of the FATEK FACON ASCII and binary protocols.

Written only from /work/shared/protocol/README.md (and its seeds where the reference is silent);
it shares no code with the C++ project so that the two can check each other.
Python 3 standard library only.

    python3 fatekref.py serve [--tcp PORT] [--udp PORT] [--station N] [--protocol auto|facon|binary]
    python3 fatekref.py client --tcp HOST:PORT|--udp HOST:PORT --protocol facon|binary --station N CMD ARGS
"""

import argparse
import asyncio
import json
import socket
import sys
import threading

STX, ETX = 0x02, 0x03
BIN_QUERY, BIN_RESPONSE, BIN_ID = 0x51, 0x52, 0x10
BIN_END = b"\x55\xAA"

# Command codes (same in both protocols).
STATUS, RUNSTOP, FORCE, FORCED, READ_BITS, WRITE_BITS = 0x40, 0x41, 0x42, 0x43, 0x44, 0x45
READ_REGS, WRITE_REGS, MIXED_READ, MIXED_WRITE = 0x46, 0x47, 0x48, 0x49
LOOPBACK, READ_PAGE, WRITE_PAGE, DETAIL = 0x4E, 0x4F, 0x50, 0x53
ALL_COMMANDS = (0x40, 0x41, 0x42, 0x43, 0x44, 0x45, 0x46, 0x47, 0x48, 0x49, 0x4E, 0x4F, 0x50, 0x53)
FACON_ONLY = (READ_PAGE, WRITE_PAGE)

FORCE_OPS = {"disable": 1, "enable": 2, "set": 3, "reset": 4}

ERROR_TEXT = {
    0: "no error", 2: "illegal value", 3: "write prohibited", 4: "illegal format or command cannot execute",
    5: "cannot RUN: ladder checksum error", 6: "cannot RUN: PLC ID differs from ladder ID",
    7: "cannot RUN: syntax check error", 9: "cannot RUN: function not supported", 0xA: "illegal address",
}


class FatekError(Exception):
    """A query that cannot be built or a frame that cannot be understood."""


class PlcError(Exception):
    """Carries a protocol error code (2, 4, A ...) while serving a query."""

    def __init__(self, code, why=""):
        super().__init__("error %X %s" % (code, why))
        self.code = code


# ---------------------------------------------------------------------------------------------
# Elements
# ---------------------------------------------------------------------------------------------

class Element:
    def __init__(self, symbol, kind, base, span, align, digits):
        self.symbol = symbol
        self.kind = kind          # bit, w16, w32, reg16, reg32
        self.base = base          # underlying memory: discrete symbol or register symbol
        self.span = span          # underlying points covered by one element
        self.align = align
        self.digits = digits      # decimal digits in FACON text
        self.words = 2 if kind in ("w32", "reg32") else 1   # weight in 48/49 budgets and 46/47 limits
        self.step = span          # consecutive reads step by the span (WY16, DR2 ...)

    @property
    def is_bit(self):
        return self.kind == "bit"

    @property
    def bits(self):
        return 1 if self.kind == "bit" else 16 * self.words

    @property
    def nbytes(self):
        return 1 if self.kind == "bit" else 2 * self.words

    @property
    def nhex(self):
        return 1 if self.kind == "bit" else 4 * self.words


ELEMENTS = {}
for _d in "XYMSTC":
    ELEMENTS[_d] = Element(_d, "bit", _d, 1, 1, 4)
    ELEMENTS["W" + _d] = Element("W" + _d, "w16", _d, 16, 8, 4)
    ELEMENTS["DW" + _d] = Element("DW" + _d, "w32", _d, 32, 8, 4)
for _r in ("RT", "RC"):
    ELEMENTS[_r] = Element(_r, "reg16", _r, 1, 1, 4)
    ELEMENTS["D" + _r] = Element("D" + _r, "reg32", _r, 2, 1, 4)
for _r in "RDF":
    ELEMENTS[_r] = Element(_r, "reg16", _r, 1, 1, 5)
    ELEMENTS["D" + _r] = Element("D" + _r, "reg32", _r, 2, 1, 5)
SYMBOLS_LONGEST_FIRST = sorted(ELEMENTS, key=len, reverse=True)

# Highest point number of each underlying memory on the largest model.
DEFAULT_LIMITS = {s: 9999 for s in "XYMSTC"}
DEFAULT_LIMITS.update({"RT": 9999, "RC": 9999, "R": 65535, "D": 65535, "F": 65535})


class Address:
    __slots__ = ("el", "number")

    def __init__(self, symbol, number):
        if symbol not in ELEMENTS:
            raise FatekError("unknown element %r" % symbol)
        self.el = ELEMENTS[symbol]
        self.number = int(number)

    @classmethod
    def parse(cls, text):
        text = text.strip().upper()
        i = 0
        while i < len(text) and text[i].isalpha():
            i += 1
        if i == 0 or i == len(text) or not text[i:].isdigit():
            raise FatekError("bad address %r" % text)
        return cls(text[:i], int(text[i:]))

    def advanced(self, k):
        return Address(self.el.symbol, self.number + k * self.el.step)

    def facon(self):
        if not 0 <= self.number < 10 ** self.el.digits:
            raise FatekError("%s not encodable in FACON" % self)
        return "%s%0*d" % (self.el.symbol, self.el.digits, self.number)

    def binary(self):
        if not 0 <= self.number <= 0xFFFF:
            raise FatekError("%s not encodable in binary" % self)
        return self.el.symbol.encode() + self.number.to_bytes(2, "big")

    def __str__(self):
        return "%s%d" % (self.el.symbol, self.number)

    __repr__ = __str__

    def __eq__(self, other):
        return isinstance(other, Address) and (self.el.symbol, self.number) == (other.el.symbol, other.number)


# ---------------------------------------------------------------------------------------------
# Typed queries and answers
# ---------------------------------------------------------------------------------------------

class Request:
    """cmd plus the fields the command uses:
    41 run(bool); 42 op(1..4), addr; 43/44/46 addr, count; 45/47 addr, values; 48 addrs;
    49 items [(addr, value)]; 4E data(bytes); 4F page; 50 page, values(64 words)."""

    def __init__(self, cmd, station=None, **kw):
        self.cmd = cmd
        self.station = station
        self.run = kw.pop("run", None)
        self.op = kw.pop("op", None)
        self.addr = kw.pop("addr", None)
        self.count = kw.pop("count", None)
        self.values = kw.pop("values", None)
        self.addrs = kw.pop("addrs", None)
        self.items = kw.pop("items", None)
        self.data = kw.pop("data", None)
        self.page = kw.pop("page", None)
        if kw:
            raise TypeError("unknown request fields %s" % list(kw))
        if self.cmd in (WRITE_BITS, WRITE_REGS) and self.count is None:
            self.count = len(self.values)

    def __repr__(self):
        f = {k: getattr(self, k) for k in ("run", "op", "addr", "count", "values", "addrs", "items", "data", "page")
             if getattr(self, k) is not None}
        return "Request(%02X, st=%d, %s)" % (self.cmd, self.station, f)


class Response:
    """error (int, None for a loopback echo); values (list) for 43 44 46 48 4F; status (bytes) for 40 53;
    data (bytes) for 4E."""

    def __init__(self, cmd, station, error=0, values=None, status=None, data=None):
        self.cmd, self.station, self.error = cmd, station, error
        self.values, self.status, self.data = values, status, data

    def to_json(self):
        d = {"station": self.station, "cmd": "%02X" % self.cmd, "error": self.error}
        if self.error:
            d["error_text"] = ERROR_TEXT.get(self.error, "unknown")
        if self.values is not None:
            d["values"] = self.values
        if self.status is not None:
            d["status"] = self.status.hex().upper()
            if self.status:
                d["run"] = bool(self.status[0] & 1)
        if self.data is not None:
            d["data"] = self.data.decode("latin-1")
        return d


def _mask(el):
    return (1 << el.bits) - 1


# ---------------------------------------------------------------------------------------------
# Checksums and frames
# ---------------------------------------------------------------------------------------------

def crc16_modbus(data):
    crc = 0xFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return crc


def lrc(data):
    return sum(data) & 0xFF


def facon_frame(station, cmd, text):
    body = bytes([STX]) + ("%02X%02X" % (station, cmd)).encode() + text.encode("latin-1")
    return body + ("%02X" % lrc(body)).encode() + bytes([ETX])


def binary_frame(header, payload):
    if len(payload) > 0xFFFF:
        raise FatekError("payload too long")
    lp = len(payload).to_bytes(2, "big") + payload
    crc = crc16_modbus(lp)
    return bytes([header, BIN_ID]) + lp + bytes([crc & 0xFF, crc >> 8]) + BIN_END


def _is_hex(b):
    return len(b) > 0 and all(c in b"0123456789ABCDEFabcdef" for c in b)


def unframe_facon(frame):
    """-> (station, cmd, data text) or None if the frame is not a valid FACON frame."""
    if len(frame) < 7 or frame[0] != STX or frame[-1] != ETX:
        return None
    body, chk = frame[:-3], frame[-3:-1]
    if not _is_hex(chk) or not _is_hex(body[1:3]) or int(chk, 16) != lrc(body):
        return None
    station = int(body[1:3], 16)
    cmd = int(body[3:5], 16) if _is_hex(body[3:5]) else None
    return station, cmd, body[5:].decode("latin-1")


def unframe_binary(frame, header):
    """-> payload bytes or None."""
    if len(frame) < 8 or frame[0] != header or frame[1] != BIN_ID or frame[-2:] != BIN_END:
        return None
    n = int.from_bytes(frame[2:4], "big")
    if len(frame) != n + 8:
        return None
    crc = crc16_modbus(frame[2:4 + n])
    if frame[4 + n] != crc & 0xFF or frame[5 + n] != crc >> 8:
        return None
    return frame[4:4 + n]


class Deframer:
    """Cuts a byte stream into complete frames. mode 'facon', 'binary' or 'auto'. header: binary byte
    expected (0x51 on a server, 0x52 on a client). Frames with bad checksums are dropped."""

    MAX_FACON = 600
    MAX_PAYLOAD = 1024

    def __init__(self, mode="auto", header=BIN_QUERY):
        self.mode, self.header = mode, header
        self.buf = bytearray()

    def feed(self, data):
        self.buf += data
        out = []
        buf = self.buf
        while buf:
            b = buf[0]
            if b == STX and self.mode in ("auto", "facon"):
                end = buf.find(bytes([ETX]))
                if end < 0:
                    restart = buf.find(bytes([STX]), 1)
                    if restart > 0:
                        del buf[:restart]
                        continue
                    if len(buf) > self.MAX_FACON:
                        del buf[:]
                    break
                restart = buf.rfind(bytes([STX]), 1, end)
                if restart > 0:          # a new STX restarts the frame
                    del buf[:restart]
                    continue
                frame = bytes(buf[:end + 1])
                del buf[:end + 1]
                if unframe_facon(frame) is not None:
                    out.append(("facon", frame))
            elif b == self.header and self.mode in ("auto", "binary"):
                if len(buf) < 4:
                    break
                n = int.from_bytes(buf[2:4], "big")
                if buf[1] != BIN_ID or n > self.MAX_PAYLOAD:
                    del buf[:1]
                    continue
                if len(buf) < n + 8:
                    break
                frame = bytes(buf[:n + 8])
                if unframe_binary(frame, self.header) is None:
                    del buf[:1]          # resynchronise on the next header byte
                    continue
                del buf[:n + 8]
                out.append(("binary", frame))
            else:
                del buf[:1]
        return out


# ---------------------------------------------------------------------------------------------
# Query encoders (client side)
# ---------------------------------------------------------------------------------------------

def _count_byte(n, allow256):
    if allow256 and n == 256:
        return 0
    if not 0 <= n <= 255:
        raise FatekError("count %d out of range" % n)
    return n


def _value_hex(el, v):
    return "%0*X" % (el.nhex, v & _mask(el)) if not el.is_bit else ("1" if v else "0")


def _value_bytes(el, v):
    return bytes([1 if v else 0]) if el.is_bit else (v & _mask(el)).to_bytes(el.nbytes, "big")


def encode_query(protocol, req):
    if req.station is None or not 0 <= req.station <= 255:
        raise FatekError("station %r" % req.station)
    if protocol == "facon":
        return facon_frame(req.station, req.cmd, facon_query_data(req))
    if req.cmd in FACON_ONLY:
        raise FatekError("command %02X exists only in FACON" % req.cmd)
    return binary_frame(BIN_QUERY, bytes([req.station, req.cmd]) + binary_query_data(req))


def facon_query_data(r):
    c = r.cmd
    if c in (STATUS, DETAIL):
        return ""
    if c == RUNSTOP:
        return "1" if r.run else "0"
    if c == FORCE:
        return "%d" % r.op + r.addr.facon()
    if c in (FORCED, READ_BITS, READ_REGS):
        return "%02X" % _count_byte(r.count, c != READ_REGS) + r.addr.facon()
    if c in (WRITE_BITS, WRITE_REGS):
        return ("%02X" % _count_byte(r.count, c == WRITE_BITS) + r.addr.facon()
                + "".join(_value_hex(r.addr.el, v) for v in r.values))
    if c == MIXED_READ:
        return "%02X" % len(r.addrs) + "".join(a.facon() for a in r.addrs)
    if c == MIXED_WRITE:
        return "%02X" % len(r.items) + "".join(a.facon() + _value_hex(a.el, v) for a, v in r.items)
    if c == LOOPBACK:
        return bytes(r.data).decode("latin-1")
    if c == READ_PAGE:
        return "%04X" % r.page
    if c == WRITE_PAGE:
        return "%04X" % r.page + "".join("%04X" % (w & 0xFFFF) for w in r.values)
    raise FatekError("unknown command %02X" % c)


def binary_query_data(r):
    c = r.cmd
    if c in (STATUS, DETAIL):
        return b""
    if c == RUNSTOP:
        return bytes([1 if r.run else 0])
    if c == FORCE:
        return bytes([r.op]) + r.addr.binary()
    if c in (FORCED, READ_BITS, READ_REGS):
        return bytes([_count_byte(r.count, c != READ_REGS)]) + r.addr.binary()
    if c in (WRITE_BITS, WRITE_REGS):
        return (bytes([_count_byte(r.count, c == WRITE_BITS)]) + r.addr.binary()
                + b"".join(_value_bytes(r.addr.el, v) for v in r.values))
    if c == MIXED_READ:
        return bytes([len(r.addrs)]) + b"".join(a.binary() for a in r.addrs)
    if c == MIXED_WRITE:
        return bytes([len(r.items)]) + b"".join(a.binary() + _value_bytes(a.el, v) for a, v in r.items)
    if c == LOOPBACK:
        return bytes(r.data)
    raise FatekError("unknown command %02X" % c)


# ---------------------------------------------------------------------------------------------
# Response decoders (client side): need the query to know the element kinds
# ---------------------------------------------------------------------------------------------

def _answer_elements(req):
    """Element of each value of the answer, in order."""
    if req.cmd in (FORCED, READ_BITS, READ_REGS):
        return [req.addr.el] * req.count
    if req.cmd == MIXED_READ:
        return [a.el for a in req.addrs]
    return []


def decode_response(protocol, frame, req):
    if protocol == "facon":
        u = unframe_facon(frame)
        if u is None:
            raise FatekError("bad FACON frame")
        station, cmd, text = u
        if cmd != req.cmd:
            raise FatekError("answer to command %s, expected %02X" % (cmd, req.cmd))
        if cmd == LOOPBACK and text == bytes(req.data).decode("latin-1"):
            return Response(cmd, station, None, data=bytes(req.data))
        if not text:
            raise FatekError("answer without error digit")
        err = int(text[0], 16)
        body = text[1:]
        if err:
            return Response(cmd, station, err)
        try:
            return _decode_facon_body(cmd, station, body, req)
        except ValueError as e:
            raise FatekError("bad answer data %r: %s" % (body, e))
    payload = unframe_binary(frame, BIN_RESPONSE)
    if payload is None or len(payload) < 2:
        raise FatekError("bad binary frame")
    station, cmd = payload[0], payload[1]
    if cmd != req.cmd:
        raise FatekError("answer to command %02X, expected %02X" % (cmd, req.cmd))
    if cmd == LOOPBACK and payload[2:] == bytes(req.data):
        return Response(cmd, station, None, data=payload[2:])
    if len(payload) < 3:
        raise FatekError("answer without error byte")
    err, body = payload[2], payload[3:]
    if err:
        return Response(cmd, station, err)
    return _decode_binary_body(cmd, station, body, req)


def _decode_facon_body(cmd, station, body, req):
    if cmd in (STATUS, DETAIL):
        return Response(cmd, station, 0, status=bytes.fromhex(body))
    if cmd == READ_PAGE:
        if len(body) != 256:
            raise ValueError("page must be 64 words")
        return Response(cmd, station, 0, values=[int(body[i:i + 4], 16) for i in range(0, 256, 4)])
    els = _answer_elements(req)
    if not els:
        if body:
            raise ValueError("unexpected data")
        return Response(cmd, station, 0)
    values, pos = [], 0
    for el in els:
        chunk = body[pos:pos + el.nhex]
        if len(chunk) != el.nhex:
            raise ValueError("too short")
        if el.is_bit and chunk not in "01":
            raise ValueError("discrete value %r" % chunk)
        values.append(int(chunk, 16))
        pos += el.nhex
    if pos != len(body):
        raise ValueError("too long")
    return Response(cmd, station, 0, values=values)


def _decode_binary_body(cmd, station, body, req):
    if cmd in (STATUS, DETAIL):
        return Response(cmd, station, 0, status=bytes(body))
    els = _answer_elements(req)
    values, pos = [], 0
    for el in els:
        chunk = body[pos:pos + el.nbytes]
        if len(chunk) != el.nbytes:
            raise FatekError("answer too short")
        values.append(int.from_bytes(chunk, "big"))
        pos += el.nbytes
    if pos != len(body):
        raise FatekError("answer too long")
    return Response(cmd, station, 0, values=values if els else None)


# ---------------------------------------------------------------------------------------------
# Reference PLC
# ---------------------------------------------------------------------------------------------

PROGRAM_WORDS = 8192                     # 8K steps: pages 0..128 (page 0 is the header)
PROGRAM_PAGES = PROGRAM_WORDS // 64 + 1


class RefPlc:
    def __init__(self, station=1, limits=None):
        self.station = station
        self.limits = dict(DEFAULT_LIMITS)
        if limits:
            self.limits.update(limits)
        self.bits = {s: bytearray(DEFAULT_LIMITS[s] + 1) for s in "XYMSTC"}
        self.disabled = {s: bytearray(DEFAULT_LIMITS[s] + 1) for s in "XYMSTC"}
        self.regs = {s: [0] * (DEFAULT_LIMITS[s] + 1) for s in ("RT", "RC", "R", "D", "F")}
        self.running = False
        self.battery_low = self.ladder_checksum_error = self.rom_pack = False
        self.watchdog = self.id_set = self.emergency = False
        self.status2 = 0
        self.program = [[0xFFFF] * 64 for _ in range(PROGRAM_PAGES)]
        # Page 0 header as in the FACON seed: "FB00", ladder size, then FF.
        header = bytes([0x46, 0x42, 0x30, 0x30, PROGRAM_WORDS >> 8, PROGRAM_WORDS & 0xFF]) + b"\xFF" * 122
        self.program[0] = [int.from_bytes(header[i:i + 2], "big") for i in range(0, 128, 2)]

    # -- memory ------------------------------------------------------------------------------

    def check(self, addr, count=1):
        el = addr.el
        if addr.number < 0 or addr.number % el.align:
            raise PlcError(0xA, "misaligned %s" % addr)
        last = addr.number + el.step * (count - 1) + el.span - 1
        if last > self.limits.get(el.base, -1):
            raise PlcError(0xA, "%s x%d beyond range" % (addr, count))

    def get(self, addr):
        el, n = addr.el, addr.number
        if el.kind == "bit":
            return self.bits[el.base][n]
        if el.kind in ("w16", "w32"):
            mem = self.bits[el.base]
            return sum(mem[n + i] << i for i in range(el.span))
        mem = self.regs[el.base]
        return mem[n] if el.kind == "reg16" else mem[n] | (mem[n + 1] << 16)

    def set(self, addr, value):
        el, n = addr.el, addr.number
        if el.kind == "bit":
            self.bits[el.base][n] = 1 if value else 0
        elif el.kind in ("w16", "w32"):
            mem = self.bits[el.base]
            for i in range(el.span):
                mem[n + i] = (value >> i) & 1
        elif el.kind == "reg16":
            self.regs[el.base][n] = value & 0xFFFF
        else:
            self.regs[el.base][n] = value & 0xFFFF
            self.regs[el.base][n + 1] = (value >> 16) & 0xFFFF

    def status1(self):
        flags = (self.running, self.battery_low, self.ladder_checksum_error, self.rom_pack,
                 self.watchdog, self.id_set, self.emergency)
        return sum(1 << i for i, f in enumerate(flags) if f)

    def detail(self):
        """64 bytes, layout of the FACON seed's command 53."""
        def w(v):
            v = min(v, 0xFFFF)
            return [v >> 8, v & 0xFF]
        lim = self.limits
        cnt = lambda s: max(lim.get(s, -1) + 1, 0)
        b = [self.status1(), 0x01, 0x02, 0x31] + w(PROGRAM_WORDS) + w(cnt("X")) + w(cnt("Y")) + w(0) + w(0)
        b += w(cnt("M")) + w(cnt("S")) + w(0) + w(cnt("R")) + w(cnt("D")) + w(cnt("T")) + w(cnt("C"))
        return bytes(b + [0] * (64 - len(b)))

    # -- execution of typed queries -----------------------------------------------------------

    def execute(self, r):
        """Runs a typed Request; returns a Response (raises PlcError)."""
        resp = self._execute(r)
        resp.elements = _answer_elements(r)     # needed to encode the values
        return resp

    def _execute(self, r):
        c = r.cmd
        if c == STATUS:
            return Response(c, self.station, 0, status=bytes([self.status1(), self.status2, 0]))
        if c == DETAIL:
            return Response(c, self.station, 0, status=self.detail())
        if c == RUNSTOP:
            if r.run:
                if self.ladder_checksum_error:
                    raise PlcError(5)
                self.running = True
            else:
                self.running = False
            return Response(c, self.station, 0)
        if c == LOOPBACK:
            return Response(c, self.station, None, data=bytes(r.data))
        if c == FORCE:
            self._need_kind(r.addr, ("bit",))
            if r.op not in (1, 2, 3, 4):
                raise PlcError(2, "force op %r" % r.op)
            self.check(r.addr)
            el, n = r.addr.el, r.addr.number
            if r.op in (1, 2):
                self.disabled[el.base][n] = 1 if r.op == 1 else 0
            else:
                self.bits[el.base][n] = 1 if r.op == 3 else 0
            return Response(c, self.station, 0)
        if c in (FORCED, READ_BITS, WRITE_BITS):
            self._need_kind(r.addr, ("bit",))
            if not 1 <= r.count <= 256:
                raise PlcError(4, "count")
            self.check(r.addr, r.count)
            el, n = r.addr.el, r.addr.number
            if c == WRITE_BITS:
                for i, v in enumerate(r.values):
                    self.bits[el.base][n + i] = v
                return Response(c, self.station, 0)
            mem = self.disabled if c == FORCED else self.bits
            return Response(c, self.station, 0, values=list(mem[el.base][n:n + r.count]))
        if c in (READ_REGS, WRITE_REGS):
            self._need_kind(r.addr, ("w16", "w32", "reg16", "reg32"))
            if not 1 <= r.count <= 64 // r.addr.el.words:
                raise PlcError(4, "count")
            self.check(r.addr, r.count)
            if c == WRITE_REGS:
                for i, v in enumerate(r.values):
                    self.set(r.addr.advanced(i), v)
                return Response(c, self.station, 0)
            return Response(c, self.station, 0, values=[self.get(r.addr.advanced(i)) for i in range(r.count)])
        if c == MIXED_READ:
            if not 1 <= len(r.addrs) or sum(a.el.words for a in r.addrs) > 64:
                raise PlcError(4, "count")
            for a in r.addrs:
                self.check(a)
            return Response(c, self.station, 0, values=[self.get(a) for a in r.addrs])
        if c == MIXED_WRITE:
            if not 1 <= len(r.items) or sum(a.el.words for a, _ in r.items) > 32:
                raise PlcError(4, "count")
            for a, _ in r.items:
                self.check(a)
            for a, v in r.items:
                self.set(a, v)
            return Response(c, self.station, 0)
        if c in (READ_PAGE, WRITE_PAGE):
            if not 0 <= r.page < PROGRAM_PAGES:
                raise PlcError(0xA, "page")
            if c == READ_PAGE:
                return Response(c, self.station, 0, values=list(self.program[r.page]))
            if self.running:
                raise PlcError(4, "program write while running")
            self.program[r.page] = list(r.values)
            return Response(c, self.station, 0)
        raise PlcError(4, "unknown command")

    @staticmethod
    def _need_kind(addr, kinds):
        if addr.el.kind not in kinds:
            raise PlcError(4, "%s not allowed for this command" % addr)

    # -- wire level -------------------------------------------------------------------------

    def handle(self, protocol, frame):
        """One complete query frame -> answer frame, or None (no answer)."""
        if protocol == "facon":
            u = unframe_facon(frame)
            if u is None:
                return None
            station, cmd, text = u
            if station != 0 and station != self.station:
                return None
            cmdtext = frame[3:5].decode("latin-1")
            try:
                if cmd is None:
                    raise PlcError(4, "command code")
                req = parse_facon_query(station, cmd, text)
                for a in _addresses(req):
                    if a.el.base in BINARY_ONLY_BASES:
                        raise PlcError(0xA, "%s exists only in the binary protocol" % a)
                resp = self.execute(req)
                answer = encode_response("facon", resp)
            except PlcError as e:
                answer = bytes([STX]) + ("%02X" % self.station + cmdtext + "%X" % e.code).encode("latin-1")
                answer += ("%02X" % lrc(answer)).encode() + bytes([ETX])
            return None if station == 0 else answer
        payload = unframe_binary(frame, BIN_QUERY)
        if payload is None or len(payload) < 2:
            return None
        station, cmd = payload[0], payload[1]
        if station != 0 and station != self.station:
            return None
        try:
            resp = self.execute(parse_binary_query(station, cmd, payload[2:]))
            answer = encode_response("binary", resp)
        except PlcError as e:
            answer = binary_frame(BIN_RESPONSE, bytes([self.station, cmd, e.code]))
        return None if station == 0 else answer


# F registers are listed by the binary protocol only (the FACON element table has no F).
BINARY_ONLY_BASES = ("F",)


def _addresses(req):
    out = [req.addr] if req.addr is not None else []
    out += list(req.addrs or []) + [a for a, _ in (req.items or [])]
    return out


def encode_response(protocol, resp):
    c = resp.cmd
    if protocol == "facon":
        if resp.error is None:
            text = resp.data.decode("latin-1")
        elif resp.error:
            text = "%X" % resp.error
        else:
            text = "0"
            if resp.status is not None:
                text += resp.status.hex().upper()
            elif resp.values is not None:
                text += _facon_values(c, resp)
        return facon_frame(resp.station, c, text)
    if resp.error is None:
        body = bytes(resp.data)
    else:
        body = bytes([resp.error])
        if not resp.error:
            if resp.status is not None:
                body += resp.status
            elif resp.values is not None:
                body += b"".join(_value_bytes(el, v) for el, v in zip(resp.elements, resp.values))
    return binary_frame(BIN_RESPONSE, bytes([resp.station, c]) + body)


def _facon_values(c, resp):
    if c == READ_PAGE:
        return "".join("%04X" % v for v in resp.values)
    return "".join(_value_hex(el, v) for el, v in zip(resp.elements, resp.values))




# ---------------------------------------------------------------------------------------------
# Query parsers (server side)
# ---------------------------------------------------------------------------------------------

HEX = set("0123456789ABCDEF")


def _hex(text, what):
    if not text or not set(text.upper()) <= HEX:
        raise PlcError(2, "%s %r is not hex" % (what, text))
    return int(text, 16)


class _FaconReader:
    def __init__(self, text):
        self.t, self.p = text, 0

    def take(self, n):
        if self.p + n > len(self.t):
            raise PlcError(4, "query too short")
        s = self.t[self.p:self.p + n]
        self.p += n
        return s

    def hex(self, n, what):
        return _hex(self.take(n), what)

    def addr(self):
        start = self.p
        while self.p < len(self.t) and self.t[self.p].isalpha() and self.t[self.p].isupper():
            self.p += 1
        sym = self.t[start:self.p]
        if sym not in ELEMENTS:
            raise PlcError(4, "element %r" % sym)
        digits = self.take(ELEMENTS[sym].digits)
        if not digits.isdigit() or not digits.isascii():
            raise PlcError(2, "address digits %r" % digits)
        return Address(sym, int(digits))

    def value(self, el):
        s = self.take(el.nhex)
        if el.is_bit:
            if s not in ("0", "1"):
                raise PlcError(2, "discrete value %r" % s)
            return int(s)
        return _hex(s, "value")

    def end(self):
        if self.p != len(self.t):
            raise PlcError(4, "trailing data")


def parse_facon_query(station, cmd, text):
    rd = _FaconReader(text)
    if cmd in (STATUS, DETAIL):
        r = Request(cmd, station)
    elif cmd == RUNSTOP:
        s = rd.take(1)
        if s not in ("0", "1"):
            raise PlcError(2, "control %r" % s)
        r = Request(cmd, station, run=s == "1")
    elif cmd == FORCE:
        s = rd.take(1)
        if s not in "1234":
            raise PlcError(2, "force op %r" % s)
        r = Request(cmd, station, op=int(s), addr=rd.addr())
    elif cmd in (FORCED, READ_BITS, READ_REGS, WRITE_BITS, WRITE_REGS):
        n = rd.hex(2, "count")
        if n == 0 and cmd in (FORCED, READ_BITS, WRITE_BITS):
            n = 256
        a = rd.addr()
        if cmd in (WRITE_BITS, WRITE_REGS):
            if cmd == WRITE_BITS and not a.el.is_bit or cmd == WRITE_REGS and a.el.is_bit:
                raise PlcError(4, "%s not allowed for this command" % a)
            r = Request(cmd, station, addr=a, values=[rd.value(a.el) for _ in range(n)])
        else:
            r = Request(cmd, station, addr=a, count=n)
    elif cmd == MIXED_READ:
        n = rd.hex(2, "count")
        r = Request(cmd, station, addrs=[rd.addr() for _ in range(n)])
    elif cmd == MIXED_WRITE:
        n = rd.hex(2, "count")
        items = []
        for _ in range(n):
            a = rd.addr()
            items.append((a, rd.value(a.el)))
        r = Request(cmd, station, items=items)
    elif cmd == LOOPBACK:
        if len(text) > 256:
            raise PlcError(4, "loopback data too long")
        return Request(cmd, station, data=text.encode("latin-1"))
    elif cmd == READ_PAGE:
        r = Request(cmd, station, page=rd.hex(4, "page"))
    elif cmd == WRITE_PAGE:
        page = rd.hex(4, "page")
        r = Request(cmd, station, page=page, values=[rd.hex(4, "word") for _ in range(64)])
    else:
        raise PlcError(4, "unknown command %02X" % cmd)
    rd.end()
    return r


def _bin_addr_at(data, pos):
    """Longest symbol at data[pos:] followed by 2 number bytes -> (Address, new pos)."""
    for sym in SYMBOLS_LONGEST_FIRST:
        s = sym.encode()
        if data[pos:pos + len(s)] == s and pos + len(s) + 2 <= len(data):
            n = int.from_bytes(data[pos + len(s):pos + len(s) + 2], "big")
            return Address(sym, n), pos + len(s) + 2
    raise PlcError(4, "element at %d" % pos)


def _bin_single_addr(rest, value_bytes_for):
    """Single-type commands: the symbol whose length makes the payload consistent.
    value_bytes_for(el) -> bytes of data expected after the address."""
    for sym in SYMBOLS_LONGEST_FIRST:
        s = sym.encode()
        if rest.startswith(s) and len(rest) == len(s) + 2 + value_bytes_for(ELEMENTS[sym]):
            return Address(sym, int.from_bytes(rest[len(s):len(s) + 2], "big")), len(s) + 2
    raise PlcError(4, "element or length")


def parse_binary_query(station, cmd, data):
    if cmd in (STATUS, DETAIL):
        if data:
            raise PlcError(4, "trailing data")
        return Request(cmd, station)
    if cmd == RUNSTOP:
        if len(data) != 1:
            raise PlcError(4, "length")
        if data[0] not in (0, 1):
            raise PlcError(2, "control %d" % data[0])
        return Request(cmd, station, run=data[0] == 1)
    if cmd == LOOPBACK:
        if len(data) > 256:
            raise PlcError(4, "loopback data too long")
        return Request(cmd, station, data=bytes(data))
    if len(data) < 1:
        raise PlcError(4, "length")
    head, rest = data[0], data[1:]
    if cmd == FORCE:
        if head not in (1, 2, 3, 4):
            raise PlcError(2, "force op %d" % head)
        a, _ = _bin_single_addr(rest, lambda el: 0)
        return Request(cmd, station, op=head, addr=a)
    if cmd in (FORCED, READ_BITS, READ_REGS):
        n = 256 if head == 0 and cmd != READ_REGS else head
        a, _ = _bin_single_addr(rest, lambda el: 0)
        return Request(cmd, station, addr=a, count=n)
    if cmd in (WRITE_BITS, WRITE_REGS):
        n = 256 if head == 0 and cmd == WRITE_BITS else head
        a, pos = _bin_single_addr(rest, lambda el: n * el.nbytes)
        if cmd == WRITE_BITS and not a.el.is_bit or cmd == WRITE_REGS and a.el.is_bit:
            raise PlcError(4, "%s not allowed for this command" % a)
        vals = []
        for i in range(n):
            chunk = rest[pos + i * a.el.nbytes:pos + (i + 1) * a.el.nbytes]
            v = int.from_bytes(chunk, "big")
            if a.el.is_bit and v > 1:
                raise PlcError(2, "discrete value %d" % v)
            vals.append(v)
        return Request(cmd, station, addr=a, values=vals)
    if cmd == MIXED_READ:
        pos, addrs = 0, []
        for _ in range(head):
            a, pos = _bin_addr_at(rest, pos)
            addrs.append(a)
        if pos != len(rest):
            raise PlcError(4, "length")
        return Request(cmd, station, addrs=addrs)
    if cmd == MIXED_WRITE:
        pos, items = 0, []
        for _ in range(head):
            a, pos = _bin_addr_at(rest, pos)
            chunk = rest[pos:pos + a.el.nbytes]
            if len(chunk) != a.el.nbytes:
                raise PlcError(4, "length")
            v = int.from_bytes(chunk, "big")
            if a.el.is_bit and v > 1:
                raise PlcError(2, "discrete value %d" % v)
            items.append((a, v))
            pos += a.el.nbytes
        if pos != len(rest):
            raise PlcError(4, "length")
        return Request(cmd, station, items=items)
    raise PlcError(4, "unknown command %02X" % cmd)


# ---------------------------------------------------------------------------------------------
# Server
# ---------------------------------------------------------------------------------------------

LOG = False        # serve --log: every frame in and out on stderr


def _show(frame):
    if frame[:1] == bytes([STX]):
        return frame.decode("latin-1").replace("\x02", "<STX>").replace("\x03", "<ETX>")
    return frame.hex(" ").upper()


def _answer(plc, proto, frame, peer):
    try:
        answer = plc.handle(proto, frame)
    except Exception as e:       # a bug here must not take the server down; say it loudly
        print("fatekref: internal error on %r: %s: %s" % (frame, type(e).__name__, e), file=sys.stderr, flush=True)
        answer = None
    if LOG:
        print("%s %s -> %s" % (peer, _show(frame), _show(answer) if answer else "(no answer)"),
              file=sys.stderr, flush=True)
    return answer


class _TcpHandler(asyncio.Protocol):
    def __init__(self, plc, mode):
        self.plc, self.deframer = plc, Deframer(mode, BIN_QUERY)

    def connection_made(self, transport):
        self.transport = transport
        self.peer = transport.get_extra_info("peername")

    def data_received(self, data):
        for proto, frame in self.deframer.feed(data):
            answer = _answer(self.plc, proto, frame, self.peer)
            if answer:
                self.transport.write(answer)


class _UdpHandler(asyncio.DatagramProtocol):
    def __init__(self, plc, mode):
        self.plc, self.mode = plc, mode

    def connection_made(self, transport):
        self.transport = transport

    def datagram_received(self, data, addr):
        # One datagram carries whole frames; a fragment is not completed by the next datagram.
        for proto, frame in Deframer(self.mode, BIN_QUERY).feed(data):
            answer = _answer(self.plc, proto, frame, addr)
            if answer:
                self.transport.sendto(answer, addr)

    def error_received(self, exc):
        pass         # ICMP "port unreachable" from a client that went away


async def start_servers(plc, tcp_port=0, udp_port=0, mode="auto", host="127.0.0.1"):
    loop = asyncio.get_running_loop()
    server = await loop.create_server(lambda: _TcpHandler(plc, mode), host, tcp_port)
    udp, _ = await loop.create_datagram_endpoint(lambda: _UdpHandler(plc, mode), local_addr=(host, udp_port))
    return server, udp, server.sockets[0].getsockname()[1], udp.get_extra_info("sockname")[1]


class BackgroundServer:
    """RefPlc served from a thread (for tests in the same process)."""

    def __init__(self, plc, mode="auto"):
        self.plc = plc
        self.loop = asyncio.new_event_loop()
        ready = threading.Event()

        def run():
            asyncio.set_event_loop(self.loop)
            self.server, self.udp, self.tcp_port, self.udp_port = self.loop.run_until_complete(
                start_servers(plc, 0, 0, mode))
            ready.set()
            self.loop.run_forever()
            self.server.close()
            self.udp.close()
            self.loop.run_until_complete(self.server.wait_closed())
            self.loop.close()

        self.thread = threading.Thread(target=run, daemon=True)
        self.thread.start()
        ready.wait(10)

    def call(self, fn):
        """Runs fn() on the server thread (memory is touched only there while serving)."""
        fut = asyncio.run_coroutine_threadsafe(self._call(fn), self.loop)
        return fut.result(5)

    @staticmethod
    async def _call(fn):
        return fn()

    def stop(self):
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join(5)


def serve_main(args):
    global LOG
    LOG = args.log
    plc = RefPlc(args.station)

    async def main():
        server, udp, tport, uport = await start_servers(plc, args.tcp, args.udp, args.protocol)
        print("listening tcp %d" % tport, flush=True)
        print("listening udp %d" % uport, flush=True)
        async with server:
            await server.serve_forever()

    try:
        asyncio.run(main())
    except KeyboardInterrupt:
        pass
    return 0


# ---------------------------------------------------------------------------------------------
# Client
# ---------------------------------------------------------------------------------------------

class Client:
    def __init__(self, transport, host, port, protocol, station=1, timeout=1.0):
        self.transport, self.addr, self.protocol = transport, (host, port), protocol
        self.station, self.timeout = station, timeout
        if transport == "tcp":
            self.sock = socket.create_connection(self.addr, timeout)
        else:
            self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
            self.sock.connect(self.addr)
        self.sock.settimeout(timeout)
        self.deframer = Deframer(protocol, BIN_RESPONSE)

    def close(self):
        self.sock.close()

    def send_raw(self, frame, expect_answer=True, timeout=None):
        """Sends bytes; returns the first complete answer frame or None on timeout."""
        self._drain()                # a late answer to an earlier query must not pass for this one
        self.sock.sendall(frame)
        self.sock.settimeout(timeout if timeout is not None else self.timeout)
        try:
            while True:
                data = self.sock.recv(4096)
                if not data:
                    raise ConnectionError("connection closed by the PLC")
                frames = (Deframer(self.protocol, BIN_RESPONSE).feed(data) if self.transport == "udp"
                          else self.deframer.feed(data))
                if frames:
                    return frames[0][1]
        except socket.timeout:
            return None
        finally:
            self.sock.settimeout(self.timeout)

    def _drain(self):
        self.deframer = Deframer(self.protocol, BIN_RESPONSE)
        self.sock.setblocking(False)
        try:
            while self.sock.recv(4096):
                pass
        except (BlockingIOError, InterruptedError):
            pass
        finally:
            self.sock.settimeout(self.timeout)

    def transact(self, req, timeout=None):
        if req.station is None:
            req.station = self.station
        frame = encode_query(self.protocol, req)
        answer = self.send_raw(frame, req.station != 0, timeout)
        if req.station == 0:
            return None
        if answer is None:
            raise TimeoutError("no answer to %r" % req)
        return decode_response(self.protocol, answer, req)

    # Convenience operations.
    def _r(self, cmd, **kw):
        return self.transact(Request(cmd, self.station, **kw))

    def status(self):
        return self._r(STATUS)

    def run(self):
        return self._r(RUNSTOP, run=True)

    def stop(self):
        return self._r(RUNSTOP, run=False)

    def read(self, addr, count=1):
        addr = _addr(addr)
        return self._r(READ_BITS if addr.el.is_bit else READ_REGS, addr=addr, count=count)

    def write(self, addr, values):
        addr = _addr(addr)
        return self._r(WRITE_BITS if addr.el.is_bit else WRITE_REGS, addr=addr, values=list(values))

    def mixed_read(self, addrs):
        return self._r(MIXED_READ, addrs=[_addr(a) for a in addrs])

    def mixed_write(self, items):
        return self._r(MIXED_WRITE, items=[(_addr(a), v) for a, v in items])

    def force(self, addr, op):
        return self._r(FORCE, op=FORCE_OPS.get(op, op), addr=_addr(addr))

    def forced(self, addr, count=1):
        return self._r(FORCED, addr=_addr(addr), count=count)

    def loopback(self, data):
        return self._r(LOOPBACK, data=data if isinstance(data, bytes) else data.encode("latin-1"))

    def detail(self):
        return self._r(DETAIL)

    def read_page(self, page):
        return self._r(READ_PAGE, page=page)

    def write_page(self, page, words):
        return self._r(WRITE_PAGE, page=page, values=list(words))


def _addr(a):
    return a if isinstance(a, Address) else Address.parse(a)


def _int(text):
    return int(text, 0)


def client_main(args):
    if bool(args.tcp) == bool(args.udp):
        print(json.dumps({"error": "give exactly one of --tcp HOST:PORT or --udp HOST:PORT"}))
        return 2
    transport, where = ("tcp", args.tcp) if args.tcp else ("udp", args.udp)
    host, _, port = where.rpartition(":")
    a = args.args
    try:
        cl = Client(transport, host or "127.0.0.1", int(port), args.protocol, args.station, args.timeout)
        c = args.command
        if c == "status":
            resps = [cl.status()]
        elif c in ("run", "stop"):
            resps = [cl.run() if c == "run" else cl.stop()]
        elif c == "read":
            resps = [cl.read(a[0], int(a[1]) if len(a) > 1 else 1)]
        elif c == "write":
            resps = [cl.write(a[0], [_int(v) for v in a[1:]])]
        elif c == "mread":
            resps = [cl.mixed_read(a)]
        elif c == "mwrite":
            resps = [cl.mixed_write([(p.split("=")[0], _int(p.split("=")[1])) for p in a])]
        elif c == "force":
            resps = [cl.force(a[0], a[1].lower())]
        elif c == "forced":
            resps = [cl.forced(a[0], int(a[1]) if len(a) > 1 else 1)]
        elif c == "loopback":
            resps = [cl.loopback(a[0] if a else "")]
        elif c == "detail":
            resps = [cl.detail()]
        elif c == "readpage":
            resps = [cl.read_page(_int(a[0]))]
        elif c == "writepage":
            words = [_int(v) for v in a[1:]]
            resps = [cl.write_page(_int(a[0]), words + [0xFFFF] * (64 - len(words)))]
        else:
            print(json.dumps({"error": "unknown command %s" % c}))
            return 2
    except (FatekError, ValueError, IndexError, OSError) as e:
        print(json.dumps({"error": str(e) or type(e).__name__}))
        return 2
    rc = 0
    for r in resps:
        if r is None:
            print(json.dumps({"broadcast": True}))
        else:
            print(json.dumps(r.to_json()))
            rc = 1 if r.error else rc
    return rc


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="mode", required=True)
    s = sub.add_parser("serve", help="reference PLC on 127.0.0.1")
    s.add_argument("--tcp", type=int, default=0)
    s.add_argument("--udp", type=int, default=0)
    s.add_argument("--station", type=int, default=1)
    s.add_argument("--protocol", choices=("auto", "facon", "binary"), default="auto")
    s.add_argument("--profile", default=None, help="accepted for compatibility; the largest ranges are used")
    s.add_argument("--log", action="store_true", help="show every frame on stderr")
    c = sub.add_parser("client", help="one query to a PLC")
    c.add_argument("--tcp")
    c.add_argument("--udp")
    c.add_argument("--protocol", choices=("facon", "binary"), default="facon")
    c.add_argument("--station", type=int, default=1)
    c.add_argument("--timeout", type=float, default=1.0)
    c.add_argument("command", help="status run stop read write mread mwrite force forced loopback detail "
                                   "readpage writepage")
    c.add_argument("args", nargs="*")
    args = ap.parse_args(argv)
    return serve_main(args) if args.mode == "serve" else client_main(args)


if __name__ == "__main__":
    sys.exit(main())
