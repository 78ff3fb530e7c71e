# SPDX-License-Identifier: GPL-3.0-or-later
"""The soak test's serial wire: a pseudo-terminal proxy between `fivebar` and grbl-sim.

The host opens HOST_LINK (a symlink to a pty slave the proxy owns, like a USB serial port); the
proxy forwards bytes to and from the firmware's pty (BOARD_LINK). Faults it can make:
  unplug()        close the host side (the port vanishes; the board keeps power and runs on),
                  then offer a new port at the same path (the cable plugged in again)
  corrupt_next()  change the first byte of the next matching line the host sends ('M' -> '*'):
                  the real firmware answers error:1 for it, as for a line garbled on the wire
  freeze()/thaw() stop forwarding both ways (a board that stops answering), bytes dropped
  inject(b)       send bytes to the board as if from another opener (0x18: a soft reset)
A power cut (grbl-sim killed) reads as EIO on the board side: the host side is closed too, and
the proxy waits for the firmware's pty to come back.

Accounting: every line forwarded to the board is queued; each ok/error:N the host receives answers
the oldest queued line (GRBL answers in order); an ALARM:N, a banner or a power cut drops the
queue (GRBL drops the lines still in its receive buffer), and an answer between a reset byte or
an ALARM:N and the banner stands for no line (GRBL answers the line it was in when the abort came,
without executing it). `sent` and `answers` list what crossed the wire.
Python 3 standard library only.
"""
import os
import select
import threading
import time
import tty

REALTIME = {ord('?'), ord('!'), ord('~'), 0x18}


def compact(line):
    """A G-code line as fivebar sends it: comments and spaces removed, upper case."""
    out, depth = [], 0
    for c in line:
        if c == ';' and depth == 0:
            break
        if c == '(':
            depth += 1
        elif c == ')' and depth:
            depth -= 1
        elif depth == 0 and not c.isspace():
            out.append(c.upper())
    return ''.join(out)


class Wire:
    def __init__(self, host_link, board_link, log_path):
        self.host_link, self.board_link = host_link, board_link
        self.lock = threading.Lock()
        self.master = None          # host side (pty master), None while unplugged
        self.board = None           # board side (firmware's pty slave), None while powered off
        self.frozen = False
        self.void = False            # after ALARM:N until the banner: answers stand for no line
        self.corrupt_prefixes = None  # tuple of line prefixes, armed by corrupt_next
        self.corrupted = None        # the line corrupted, once done
        self.pending_in = b''        # host -> board bytes of the line being received
        self.pending_out = b''       # board -> host bytes of the line being received
        self.queue = []              # lines forwarded, not yet answered
        self.sent = []               # every line forwarded to the board, in order
        self.answers = []            # (line, answer) delivered to the host, in order
        self.log = open(log_path, 'w', buffering=1)
        self.stop_flag = False
        self._plug()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    # -- faults ---------------------------------------------------------------------------
    def unplug(self, seconds=0.3):
        with self.lock:
            self._unplug_locked('unplugged')
        time.sleep(seconds)
        with self.lock:
            if self.board is not None and self.master is None:
                self._plug()

    def freeze(self):
        with self.lock:
            self.frozen = True
            self.log.write('%.3f FREEZE\n' % time.time())

    def thaw(self):
        with self.lock:
            self.frozen = False
            self.pending_in = b''
            self.log.write('%.3f THAW\n' % time.time())

    def corrupt_next(self, prefixes):
        with self.lock:
            self.corrupted = None
            self.corrupt_prefixes = tuple(prefixes)

    def inject(self, data):
        with self.lock:
            if self.board is not None:
                os.write(self.board, data)
                if 0x18 in data:
                    self.void = True

    def host_connected(self):
        with self.lock:
            return self._host_open()

    def close(self):
        self.stop_flag = True
        self.thread.join(2)

    # -- internals ------------------------------------------------------------------------
    def _plug(self):
        """A new host-side pty at host_link (needs the board side)."""
        if self.board is None:
            if not os.path.exists(self.board_link):
                return
            try:
                self.board = os.open(self.board_link, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
                tty.setraw(self.board)
            except OSError:
                self.board = None
                return
        master, slave = os.openpty()
        tty.setraw(slave)
        name = os.ttyname(slave)
        os.close(slave)
        os.set_blocking(master, False)
        tmp = self.host_link + '.new'
        if os.path.lexists(tmp):
            os.remove(tmp)
        os.symlink(name, tmp)
        os.replace(tmp, self.host_link)
        self.master = master
        self.pending_out = b''
        self.log.write('%.3f PLUG %s\n' % (time.time(), name))

    def _unplug_locked(self, why):
        if self.master is not None:
            os.close(self.master)
            self.master = None
            if os.path.lexists(self.host_link):
                os.remove(self.host_link)
            self.log.write('%.3f UNPLUG (%s)\n' % (time.time(), why))
        self.pending_in = b''

    def _host_open(self):
        """True while some process has the host side open (else bytes are lost, as on a port
        nobody listens to)."""
        if self.master is None:
            return False
        p = select.poll()
        p.register(self.master, select.POLLIN)
        return not any(ev & select.POLLHUP for _, ev in p.poll(0))

    def _flush(self, why):
        if self.queue:
            self.log.write('%.3f FLUSH %d lines (%s)\n' % (time.time(), len(self.queue), why))
        self.queue = []

    def _from_host(self, data):
        """Real-time bytes pass at once; a line passes whole once its end arrives."""
        out = bytearray()
        for b in data:
            if b in REALTIME or b >= 0x80:
                out.append(b)
                if b == 0x18:
                    self.pending_in = b''
                    self.void = True
            elif b in (0x0A, 0x0D):
                line = self.pending_in.decode('latin-1')
                self.pending_in = b''
                wire = line
                if self.corrupt_prefixes and line.startswith(self.corrupt_prefixes):
                    self.corrupt_prefixes = None
                    self.corrupted = line
                    wire = '*' + line[1:]
                    self.log.write('%.3f CORRUPT %s\n' % (time.time(), line))
                self.queue.append(line)
                self.sent.append(line)
                self.log.write('S %s\n' % line)
                out += wire.encode('latin-1') + bytes([b])
            else:
                self.pending_in += bytes([b])
        return bytes(out)

    def _from_board(self, data):
        self.pending_out += data
        lines = []
        while b'\n' in self.pending_out:
            line, self.pending_out = self.pending_out.split(b'\n', 1)
            lines.append(line + b'\n')
        return lines

    def _run(self):
        while not self.stop_flag:
            with self.lock:
                fds = [fd for fd in (self.board, self.master if self._host_open() else None)
                       if fd is not None]
            if not fds:
                time.sleep(0.01)
                with self.lock:
                    if self.board is None and os.path.exists(self.board_link):
                        self._plug()
                continue
            try:
                ready, _, _ = select.select(fds, [], [], 0.01)
            except (OSError, ValueError):
                continue
            with self.lock:
                for fd in ready:
                    if fd != self.board and fd != self.master:
                        continue
                    try:
                        data = os.read(fd, 4096)
                    except BlockingIOError:
                        continue
                    except OSError:
                        data = b''
                    if fd == self.board and not data:  # power cut: the firmware's pty is gone
                        os.close(self.board)
                        self.board = None
                        self._flush('power cut')
                        self._unplug_locked('power cut')
                        continue
                    if fd == self.master:
                        if not data or self.frozen or self.board is None:
                            continue
                        os.write(self.board, self._from_host(data))
                    else:
                        for line in self._from_board(data):
                            self._deliver(line)

    def _deliver(self, raw):
        text = raw.decode('latin-1').strip()
        if text.startswith('Grbl '):
            self._flush('banner')
            self.void = False
        elif text.startswith('ALARM:'):
            # Nothing read before the alarm runs any more; GRBL may still answer the line it was
            # waiting to plan (an ok after ALARM:3, for a line it never executed). Likewise after
            # a reset byte (self.void set where it is sent), until the banner.
            self._flush('alarm')
            self.void = True
        delivered = not self.frozen and self._host_open()
        if text == 'ok' or text.startswith('error:'):
            line = self.queue.pop(0) if self.queue and not self.void else None
            if delivered:
                self.answers.append((line, text))
                self.log.write('A %s %s\n' % (line, text))
        if delivered:
            try:
                os.write(self.master, raw)
            except OSError:
                pass
