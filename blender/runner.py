# The softbody program as a child process: its "progress DONE TOTAL" lines (export --progress-lines) read on a
# thread, its messages kept, terminated on Cancel (SIGTERM: softbody stops within one simulation step).
import subprocess
import threading


class ProgramRun:
    def __init__(self, program, args, cwd):
        self.command = [program] + list(args)
        self.done = 0
        self.total = 0
        self.cancelled = False
        self._messages = []
        self._summary = []
        self._process = subprocess.Popen(self.command, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, text=True, errors="replace")
        self._readers = [threading.Thread(target=self._read_progress, daemon=True),
                         threading.Thread(target=self._read_messages, daemon=True)]
        for reader in self._readers:
            reader.start()

    def _read_progress(self):
        for line in self._process.stdout:
            parts = line.split()
            if len(parts) == 3 and parts[0] == "progress":
                self.done, self.total = int(parts[1]), int(parts[2])
            elif line.strip():
                self._summary.append(line.rstrip())

    def _read_messages(self):
        for line in self._process.stderr:
            self._messages.append(line.rstrip())

    def running(self):
        return self._process.poll() is None

    def wait(self, timeout=None):
        status = self._process.wait(timeout)
        for reader in self._readers:
            reader.join()
        return status

    def cancel(self):
        """Asks the program to stop (SIGTERM), then kills it if it has not ended within 5 s."""
        self.cancelled = True
        if self.running():
            self._process.terminate()
            try:
                self._process.wait(5)
            except subprocess.TimeoutExpired:
                self._process.kill()
        self.wait()

    @property
    def returncode(self):
        return self._process.returncode

    def summary(self):
        return self._summary[-1] if self._summary else ""

    def error_message(self):
        """What the program said went wrong: its "error:" lines, else its last lines."""
        errors = [line for line in self._messages if line.startswith("error")]
        lines = errors or self._messages[-3:] or ["exit status %s" % self.returncode]
        return "; ".join(lines)

    def notes(self):
        return [line for line in self._messages if line.startswith("note")]
