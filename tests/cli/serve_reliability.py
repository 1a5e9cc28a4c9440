#!/usr/bin/env python3
"""Issue 42's defects of `oasis serve`, each kept as a case: directory URLs, a /dev/zero link and a
FIFO in the folder (the server survives each and keeps serving); a silent client does not stall a
second one; 200 concurrent connections are all answered or refused quickly; nothing outside the
folder is served (a symlink out, the sibling folder www2 when serving www, "..", "%2e%2e", "%2f");
the MIME types; the log escapes the control bytes of a request target; it listens on loopback only.
Loopback only, every wait bounded: the test stops by itself.
usage: serve_reliability.py OASIS OUT_DIR"""
import os
import shutil
import socket
import subprocess
import sys
import threading
import time

oasis, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
www, www2 = os.path.join(out, "www"), os.path.join(out, "www2")
os.makedirs(os.path.join(www, "sub"))
os.makedirs(os.path.join(www, "withindex"))
os.makedirs(www2)
SECRET = b"SECRET-OUTSIDE-THE-FOLDER"
files = {"oasis.html": b"<!doctype html><title>oasis</title>\n", "page.wasm": b"\0asm\1\0\0\0", "app.js": b"let a = 1;\n",
         "data.json": b"{}\n", "pic.png": b"\x89PNG\r\n\x1a\n", "withindex/index.html": b"<p>index</p>\n"}
for name, body in files.items():
    with open(os.path.join(www, name), "wb") as f:
        f.write(body)
with open(os.path.join(www2, "secret.txt"), "wb") as f:
    f.write(SECRET)
with open(os.path.join(out, "secret.txt"), "wb") as f:
    f.write(SECRET)
os.symlink(os.path.join(www2, "secret.txt"), os.path.join(www, "out.txt"))
os.symlink("../www2", os.path.join(www, "outdir"))
os.symlink("/dev/zero", os.path.join(www, "zero"))
os.mkfifo(os.path.join(www, "fifo"))
failures, cases = [], 0

port = 20000 + os.getpid() % 1000
# --host takes a numeric address: anything else is exit 2 before listening (killed after 10 s if not).
for host in ["nonsense", "127.0.0.1x", ""]:
    cases += 1
    try:
        bad = subprocess.run([oasis, "serve", "--dir", www, "--port", str(port), "--host", host], capture_output=True,
                             text=True, timeout=10)
        if bad.returncode != 2 or "--host expects a numeric address" not in bad.stderr:
            failures.append(f"oasis serve --host {host!r}: exit {bad.returncode}, {bad.stderr.strip()!r}")
    except subprocess.TimeoutExpired:
        failures.append(f"oasis serve --host {host!r} was still running after 10 s")

log_path = os.path.join(out, "serve.err")
log = open(log_path, "wb")
server = subprocess.Popen([oasis, "serve", "--dir", www, "--port", str(port)], stdout=subprocess.PIPE, stderr=log)


def exchange(raw, timeout=5.0):
    """Sends `raw` on a new connection; the status code and body, or (None, why)."""
    reply = b""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
            s.settimeout(timeout)
            s.sendall(raw)
            while True:
                chunk = s.recv(65536)
                if not chunk:
                    break
                reply += chunk
    except OSError as e:
        if not reply:  # refused, reset or timed out before a reply: the caller judges which
            return None, repr(e)
    head, _, body = reply.partition(b"\r\n\r\n")
    parts = head.split(b" ")
    return (int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else None), body


def get(target):
    return exchange(b"GET " + target + b" HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")


def header(target, name):
    reply = b""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
            s.settimeout(5)
            s.sendall(b"GET " + target + b" HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
            while b"\r\n\r\n" not in reply:
                chunk = s.recv(4096)
                if not chunk:
                    break
                reply += chunk
    except OSError:
        return None
    for line in reply.split(b"\r\n"):
        if line.lower().startswith(name.lower() + b":"):
            return line.split(b":", 1)[1].strip().decode()
    return None


def still_serving(after):
    """The server is alive and serves the page after case `after`."""
    if server.poll() is not None:
        failures.append(f"after {after}: the server exited with {server.returncode}")
        return False
    status, body = get(b"/oasis.html")
    if status != 200 or body != files["oasis.html"]:
        failures.append(f"after {after}: GET /oasis.html gave {status}")
        return False
    return True


def case(name, raw, want=None, forbid_secret=False, within=3.0):
    """Sends `raw`; the reply's status is `want` (any when None), in `within` seconds, never
    holding the secret; the server then still serves."""
    global cases
    cases += 1
    start = time.monotonic()
    status, body = exchange(raw, timeout=within + 2)
    took = time.monotonic() - start
    if want is not None and status != want:
        failures.append(f"{name}: status {status}, expected {want}")
    if forbid_secret and (status == 200 or (isinstance(body, bytes) and SECRET in body)):
        failures.append(f"{name}: served {status} {body[:60]!r}: outside the folder")
    if took > within:
        failures.append(f"{name}: took {took:.1f} s")
    still_serving(name)


try:
    line = server.stdout.readline().decode()
    if f"http://127.0.0.1:{port}/" not in line:
        failures.append(f"oasis serve printed {line!r}")
    for attempt in range(50):
        if get(b"/oasis.html")[0] == 200:
            break
        time.sleep(0.1)

    # Defect 1: directory URLs crashed it (std::__ios_failure "Is a directory"); /dev/zero ate memory.
    for target in [b"/.", b"/sub", b"/sub/", b"//", b"/withindex/.."]:
        case(f"GET {target.decode()}", b"GET " + target + b" HTTP/1.1\r\n\r\n", want=404)
    case("a bare GET", b"GET\r\n\r\n")
    case("GET ?", b"GET ? HTTP/1.1\r\n\r\n")
    status, body = get(b"/withindex/")
    cases += 1
    if status != 200 or body != files["withindex/index.html"]:
        failures.append(f"GET /withindex/: {status} {body!r}, expected its index.html")
    case("GET /zero (a link to /dev/zero)", b"GET /zero HTTP/1.1\r\n\r\n", want=404)
    # Defect 2: a FIFO blocked it forever.
    case("GET /fifo (a FIFO)", b"GET /fifo HTTP/1.1\r\n\r\n", want=404)

    # Defect 3: nothing outside the folder, whichever way it is named.
    for target in [b"/out.txt", b"/outdir/secret.txt", b"2/secret.txt", b"/../www2/secret.txt", b"/../secret.txt",
                   b"/%2e%2e/secret.txt", b"/%2E%2E/www2/secret.txt", b"/..%2fsecret.txt", b"/%2e%2e%2fsecret.txt",
                   b"/sub/../../www2/secret.txt", b"/sub/%2e%2e/%2e%2e/www2/secret.txt", b"/%2fsecret.txt",
                   b"//..//secret.txt", b"/./../secret.txt", b"../secret.txt", b"%2e%2e/secret.txt",
                   b"http://x/../secret.txt"]:
        case(f"GET {target.decode()}", b"GET " + target + b" HTTP/1.1\r\n\r\n", forbid_secret=True)

    # The MIME types a browser insists on.
    for name, kind in [("page.wasm", "application/wasm"), ("app.js", "text/javascript"),
                       ("oasis.html", "text/html; charset=utf-8"), ("data.json", "application/json"),
                       ("pic.png", "image/png")]:
        cases += 1
        got = header(b"/" + name.encode(), b"Content-Type")
        if got != kind:
            failures.append(f"GET /{name}: Content-Type {got!r}, expected {kind!r}")

    # Defect 2: a client that sends nothing, and one that stops half-way, do not stall a second.
    cases += 1
    try:
        silent = socket.create_connection(("127.0.0.1", port), timeout=5)
        half = socket.create_connection(("127.0.0.1", port), timeout=5)
        half.sendall(b"GET /oasis.html HTTP/1.1\r\nHost")
        time.sleep(0.2)
        start = time.monotonic()
        status, _ = get(b"/oasis.html")
        took = time.monotonic() - start
        if status != 200 or took > 1.0:
            failures.append(f"beside a silent client: status {status} in {took:.2f} s")
        silent.close()
        half.close()
    except OSError as e:
        failures.append(f"beside a silent client: {e!r}")

    # Defect 2: 200 concurrent connections, each answered or refused, none left hanging.
    cases += 1
    results = [None] * 200
    def one(i):
        status, body = exchange(b"GET /page.wasm HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", timeout=15)
        results[i] = status if status is not None else "refused"
    start = time.monotonic()
    threads = [threading.Thread(target=one, args=(i,)) for i in range(200)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=30)
    took = time.monotonic() - start
    answered = sum(1 for r in results if r == 200)
    refused = sum(1 for r in results if r == "refused")
    hung = sum(1 for t in threads if t.is_alive())
    print(f"oasis serve: 200 concurrent connections: {answered} answered, {refused} refused, {hung} hanging, "
          f"{took:.2f} s")
    if hung or answered + refused != 200 or took > 20:
        failures.append(f"200 concurrent: {answered} answered, {refused} refused, {hung} hanging in {took:.1f} s: "
                        f"{[r for r in results if r not in (200, 'refused')][:5]}")
    still_serving("200 concurrent connections")

    # Defect 4: the request target reaches the log escaped (a raw ESC could erase or fake lines).
    cases += 1
    exchange(b"GET /\x1b[2J\x1b[1Afake\rline\x7f\xff HTTP/1.1\r\n\r\n")
    still_serving("a target holding control bytes")

    # It listens on loopback only: this machine's other address, if it has one, is refused.
    probe = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    try:
        probe.connect(("10.255.255.255", 1))
        address = probe.getsockname()[0]
    except OSError:
        address = "127.0.0.1"
    probe.close()
    if not address.startswith("127."):
        cases += 1
        try:
            socket.create_connection((address, port), timeout=2).close()
            failures.append(f"a connection to {address}:{port} was accepted: not loopback only")
        except OSError:
            pass
finally:
    server.terminate()
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        server.kill()
        server.wait()
    log.close()

err = open(log_path, "rb").read()
if b"\x1b" in err or b"\r" in err or b"\x7f" in err or b"\xff" in err:
    failures.append(f"the log holds a raw control byte: {err[-300:]!r}")
if b"\\u001B[2J\\u001B[1Afake\\rline\\u007F\\xFF" not in err:
    failures.append(f"the log lacks the escaped target: {err[-300:]!r}")
for failure in failures:
    print("FAIL:", failure)
print(f"serve reliability: {cases} cases, {len(failures)} failures")
sys.exit(1 if failures else 0)
