#!/usr/bin/env python3
# A measurement, not a ctest (docs/benchmarks/study-server.md, "Study server beside hostile sockets"): the
# server's resident memory with N clients that each ask for one file and never read it.
#   python3 tests/web_server/slow_readers_rss.py VIMG SITE_DIR N [FILE]
# SITE_DIR is a built site (or any folder with an index.html); FILE defaults to /vimg.wasm.
import re, resource, socket, subprocess, sys, time

vimg, site, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
target = sys.argv[4] if len(sys.argv) > 4 else "/vimg.wasm"
resource.setrlimit(resource.RLIMIT_NOFILE, (n + 100, max(n + 100, resource.getrlimit(resource.RLIMIT_NOFILE)[1])))
server = subprocess.Popen([vimg, "serve", site, "--port", "0"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
port = int(re.search(r":(\d+)/", server.stdout.readline()).group(1))

def rss_kib():
    for line in open(f"/proc/{server.pid}/status"):
        if line.startswith("VmRSS"):
            return int(line.split()[1])

before = rss_kib()
clients = []
for _ in range(n):
    s = socket.create_connection(("127.0.0.1", port))
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.sendall(f"GET {target} HTTP/1.1\r\nHost: x\r\n\r\n".encode())
    clients.append(s)
# Every request has been read and its reply's write is pending once the server's RSS stops moving.
last, still = -1, 0
while still < 5:
    time.sleep(0.2)
    now = rss_kib()
    still = still + 1 if now == last else 0
    last = now
print(f"{n} readers of {target} that never read: server VmRSS {before} KiB before, {last} KiB with them "
      f"({(last - before) / 1024:.1f} MiB more)")
for s in clients:
    s.close()
server.terminate()
server.wait()
