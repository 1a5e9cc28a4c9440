#!/usr/bin/env python3
"""Issue 42, defect 8: text that came from outside reaches the terminal escaped. ESC, CR, LF, NUL
and invalid UTF-8 are fed through each command that echoes input (file names on the command line,
a PNG's provenance in compare --reference, the strings of a report in check --diff, serve's folder)
and no raw control byte, nor a line the input forged, may reach stdout or stderr.
usage: echo_escaped.py OASIS WORK_DIR"""
import json
import os
import shutil
import struct
import subprocess
import sys
import zlib

oasis, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)
EVIL = "\x1b[1A\x1b[2K\rFORGED\nFORGED\x07\x7f"   # ESC sequences, CR, LF, BEL, DEL
EVIL_BYTES = EVIL.encode() + b"\xff\xc0\xaf"        # and invalid UTF-8
failures, cases = [], 0


def check(name, argv, want_code=None, escaped=True):
    """Runs oasis; its stdout and stderr hold no raw control byte but LF, and no line the input forged."""
    global cases
    cases += 1
    run = subprocess.run(argv, capture_output=True, timeout=120)
    for stream, data in (("stdout", run.stdout), ("stderr", run.stderr)):
        raw = sorted({b for b in data if (b < 0x20 and b != 0x0a) or b == 0x7f})
        if raw:
            failures.append(f"{name}: {stream} holds raw bytes {raw}: {data[-300:]!r}")
        if any(line.startswith(b"FORGED") for line in data.split(b"\n")):
            failures.append(f"{name}: {stream} holds a line the input forged: {data[-300:]!r}")
        try:
            data.decode("utf-8")
        except UnicodeDecodeError as e:
            failures.append(f"{name}: {stream} is not UTF-8 ({e}): {data[-300:]!r}")
    if want_code is not None and run.returncode != want_code:
        failures.append(f"{name}: exit {run.returncode}, expected {want_code}: {run.stderr[-300:]!r}")
    if escaped and b"\\u001B" not in run.stdout + run.stderr:
        failures.append(f"{name}: the escaped ESC (\\u001B) is not printed: {run.stderr[-300:]!r}")
    return run


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(width, height, texts):
    """An RGBA PNG with the given (keyword, bytes) iTXt chunks."""
    raw = b"".join(b"\0" + b"\x40\x80\xc0\xff" * width for _ in range(height))
    itxt = b"".join(chunk(b"iTXt", key.encode() + b"\0\0\0\0\0" + value) for key, value in texts)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) + itxt +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


# A file name on the command line, in the argument error and in "cannot read NAME".
check("render: an unknown option", [oasis, "render", "--bogus" + EVIL], want_code=2)
check("compare --reference NAME (missing)", [oasis.encode(), b"compare", b"--reference", EVIL_BYTES + b".png"],
      want_code=2)

check("render --out NAME (wrote NAME)", [oasis.encode(), b"render", b"--size", b"32x18", b"--out",
                                        b"r" + EVIL_BYTES + b".png"], want_code=0)

# A received PNG's provenance: its options (refused, quoted), its renderer and version (printed).
base = [("oasis:view", b"final"), ("oasis:pipeline", b"deferred"), ("oasis:legend", b"off")]
with open("bad-options.png", "wb") as f:
    f.write(png(64, 36, base + [("oasis:options", b"--size 64x36 " + EVIL_BYTES), ("oasis:version", EVIL_BYTES)]))
check("compare --reference: evil oasis:options", [oasis, "compare", "--reference", "bad-options.png"], want_code=2)
with open("bad-renderer.png", "wb") as f:
    f.write(png(64, 36, base + [("oasis:options", b"--size 64x36"), ("oasis:version", b"0.1 " + EVIL_BYTES),
                               ("oasis:renderer", b"llvmpipe " + EVIL_BYTES)]))
check("compare --reference: evil oasis:renderer", [oasis, "compare", "--reference", "bad-renderer.png", "--out-dir",
                                                   "cmp"])
with open("bad-view.png", "wb") as f:
    f.write(png(64, 36, [("oasis:view", b"final" + EVIL_BYTES), ("oasis:pipeline", b"deferred"),
                         ("oasis:legend", b"off"), ("oasis:options", b"--size 64x36")]))
check("compare --reference: evil oasis:view", [oasis, "compare", "--reference", "bad-view.png"], want_code=2)

# check --diff: a report's strings (names, reasons, renderer) and its path.
def report(renderer, cases_):
    return {"schema": "oasis-check/1", "driver": {"renderer": renderer, "vendor": EVIL, "version": "4.5", "api": "gl"},
            "oasis": {"version": "0.1", "commit": EVIL}, "cases": cases_}
case_a = {"name": "c" + EVIL, "verdict": "pass", "reason": "ok" + EVIL, "psnr_db": 50, "max_abs": 1, "pixels_over": 0}
case_b = dict(case_a, verdict="fail", reason="bad" + EVIL)
with open("a.json", "w") as f:
    json.dump(report("llvmpipe" + EVIL, [case_a]), f)
with open("b" + EVIL.replace("\n", "").replace("/", "") + ".json", "w") as f:
    json.dump(report("other" + EVIL, [case_b]), f)
check("check --diff: evil strings", [oasis, "check", "--diff", "a.json", "b" + EVIL.replace("\n", "").replace("/", "") + ".json"],
      want_code=1)
with open("nul.json", "w") as f:
    f.write(json.dumps(report("r", [case_a])).replace('"ok', '"ok\\u0000'))
check("check --diff: a NUL", [oasis, "check", "--diff", "a.json", "nul.json" + EVIL], want_code=2)
run = subprocess.run([oasis, "check", "--diff", "a.json", "nul.json"], capture_output=True, timeout=60)
cases += 1
if run.returncode != 2 or b"a string holds a NUL" not in run.stderr:
    failures.append(f"check --diff with a NUL: exit {run.returncode}, {run.stderr[-300:]!r}")
with open("invalid.json", "wb") as f:
    f.write(json.dumps(report("r", [case_a])).encode().replace(b'"ok', b'"ok\xff\x1b'))
check("check --diff: invalid UTF-8 and a raw ESC", [oasis, "check", "--diff", "a.json", "invalid.json"],
      want_code=2, escaped=False)

# serve: the folder named.
check("serve --dir NAME (missing)", [oasis, "serve", "--dir", EVIL, "--port", "1"], want_code=1)

for failure in failures:
    print("FAIL:", failure)
print(f"echo escaped: {cases} cases, {len(failures)} failures")
sys.exit(1 if failures else 0)
