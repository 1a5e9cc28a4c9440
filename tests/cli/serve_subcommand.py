#!/usr/bin/env python3
"""`oasis serve` is oasis-serve (the web build's page server, docs/web.md): it serves a directory on
127.0.0.1 with the MIME types browsers insist on, and its bad port is refused with exit 2 as
oasis-serve's own.
usage: serve_subcommand.py OASIS OUT_DIR"""
import os
import subprocess
import sys
import time
import urllib.request

oasis, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "page.wasm"), "wb") as f:
    f.write(b"\0asm\1\0\0\0")
with open(os.path.join(out, "oasis.html"), "w") as f:  # the server wants the page it serves
    f.write("<!doctype html><title>oasis</title>\n")
failures = []

bad = subprocess.run([oasis, "serve", "--port", "99999"], capture_output=True, text=True, timeout=20)
if bad.returncode != 2 or "--port expects a port in 1..65535" not in bad.stderr:
    failures.append(f"oasis serve --port 99999: exit {bad.returncode}, {bad.stderr.strip()!r}")

port = 19000 + os.getpid() % 1000
server = subprocess.Popen([oasis, "serve", "--dir", out, "--port", str(port)], stdout=subprocess.PIPE, text=True)
try:
    line = server.stdout.readline()
    if f"http://127.0.0.1:{port}/" not in line:
        failures.append(f"oasis serve printed {line!r}")
    for attempt in range(50):
        try:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/page.wasm", timeout=5) as reply:
                body, kind = reply.read(), reply.headers["Content-Type"]
            break
        except OSError:
            time.sleep(0.1)
    else:
        body, kind = b"", None
    print(f"oasis serve: GET /page.wasm -> {kind}, {len(body)} bytes")
    if kind != "application/wasm" or body != b"\0asm\1\0\0\0":
        failures.append(f"GET /page.wasm gave {kind!r} and {body!r}")
finally:
    server.terminate()
    server.wait(timeout=10)

for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
