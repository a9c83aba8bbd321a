#!/usr/bin/env python3
"""Waits for one LCM message on a channel, with nothing but a UDP socket (no LCM bindings for
Python here): tests/arm64/systemcore_bundle.sh runs it beside the emulated arm64 daemon, in the
same private network namespace, to see ARM_DAEMON_STATUS published over the loopback route.

    lcm_channel_listener.py URL CHANNEL TIMEOUT_S READY_FILE

URL is the daemon's udpm://GROUP:PORT?... URL. READY_FILE is created once the socket has joined
the group (so the daemon is started only then). Exit 0 and one line (sequence number, payload
size) on the first message on CHANNEL; exit 1 after TIMEOUT_S without one.

LCM's UDP multicast transport sends a message that fits one datagram as: the magic 'LC02'
(uint32, big-endian), a sequence number (uint32), the channel name and a zero byte, then the
payload (the encoded type: an 8-byte fingerprint, then the fields). Larger ones are fragments
('LC03'); ARM_DAEMON_STATUS is far smaller than one datagram.
"""
import pathlib
import socket
import struct
import sys
import time
import urllib.parse

SHORT_MESSAGE_MAGIC = 0x4C433032
FINGERPRINT_BYTES = 8


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    url, channel, timeout_s, ready_file = sys.argv[1], sys.argv[2].encode(), float(sys.argv[3]), sys.argv[4]
    parsed = urllib.parse.urlparse(url)
    if parsed.scheme != 'udpm' or not parsed.hostname or not parsed.port:
        sys.exit('not a udpm://GROUP:PORT URL: %s' % url)
    listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
    listener.bind(('', parsed.port))
    membership = struct.pack('4s4s', socket.inet_aton(parsed.hostname), socket.inet_aton('0.0.0.0'))
    listener.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
    pathlib.Path(ready_file).touch()

    deadline = time.monotonic() + timeout_s
    seen = 0
    while time.monotonic() < deadline:
        listener.settimeout(max(0.01, deadline - time.monotonic()))
        try:
            datagram = listener.recv(65536)
        except socket.timeout:
            break
        seen += 1
        if len(datagram) < 9 or struct.unpack('>I', datagram[:4])[0] != SHORT_MESSAGE_MAGIC:
            continue
        name_end = datagram.find(b'\0', 8)
        if name_end < 0 or datagram[8:name_end] != channel:
            continue
        payload = datagram[name_end + 1:]
        if len(payload) <= FINGERPRINT_BYTES:
            sys.exit('%s message with a %d-byte payload' % (channel.decode(), len(payload)))
        print('%s: sequence %d, %d-byte payload' % (channel.decode(), struct.unpack('>I', datagram[4:8])[0],
                                                     len(payload)))
        return
    sys.exit('no %s message within %.0f s (%d datagrams seen)' % (channel.decode(), timeout_s, seen))


main()
