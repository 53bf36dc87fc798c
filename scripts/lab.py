"""Start JupyterLab for ``make lab``: 127.0.0.1 only, a fresh random token, and the URL printed in full.

Usage (what ``make lab`` runs; ``make -n lab`` shows it)::

    .venv/bin/python scripts/lab.py [JUPYTER OPTIONS ...] [NOTEBOOK]

Jupyter Server prints ``http://127.0.0.1:8888/lab?token=...`` with literal dots when the token
is given to it rather than made by it, and no other line carries the token.  So this script
makes the token (:func:`secrets.token_hex`, new at every start), starts JupyterLab in this
process with it, lets Jupyter show it as it shows a token of its own, and, once the server
listens, prints the URL to open (the notebook given, token included): it works when pasted into
a browser on this machine or at the end of an ssh tunnel (``ssh -L 8888:127.0.0.1:8888 host``).

The server's address, remote access and token are set after the options given here, on
Jupyter's command line (which no configuration file overrides): they cannot be switched off.
The token is not on any process's command line, so ``ps`` does not show it to other users.
"""
from __future__ import annotations

import secrets
import sys
import urllib.parse
from pathlib import Path

#: Always last on Jupyter's command line, so that they win over the caller's options and every
#: configuration file: loopback only, no remote access, the token (filled in at start).
FORCED = ("--ServerApp.ip=127.0.0.1", "--ServerApp.allow_remote_access=False")
#: First, so the caller may override it: kernel messages sent at once (planargeo.widgets.server).
PROMPT = "--ServerApp.kernel_websocket_connection_class=planargeo.widgets.server.PromptKernelConnection"


def lab_url(serverapp, token: str) -> str:
    """The URL to open: this server, the notebook given on the command line (else JupyterLab's
    start page), and the token."""
    from jupyter_server.utils import url_path_join

    path = serverapp.default_url
    if serverapp.file_to_run:
        try:
            rel = Path(serverapp.file_to_run).absolute().relative_to(Path(serverapp.root_dir).absolute())
            path = url_path_join(serverapp.base_url, serverapp.file_url_prefix, *rel.parts)
        except ValueError:
            pass
    return f"http://127.0.0.1:{serverapp.port}{path}?{urllib.parse.urlencode({'token': token})}"


def main(argv: list[str]) -> int:
    from jupyterlab.labapp import LabApp

    for a in argv:
        key = a.split("=", 1)[0].lstrip("-").lower()
        if key == "ip" or key.endswith((".ip", "token", ".allow_remote_access")):
            print(f"make lab: {a.split('=', 1)[0]} is set by scripts/lab.py (127.0.0.1 only, a fresh token at "
                  "every start) and cannot be changed", file=sys.stderr)
            return 2
    token = secrets.token_hex(24)
    serverapp = LabApp.initialize_server(argv=[PROMPT, *argv, *FORCED, f"--IdentityProvider.token={token}"])
    if serverapp.ip != "127.0.0.1" or serverapp.identity_provider.token != token:   # belt and braces
        print("make lab: refusing to start: the server would not be on 127.0.0.1 with the token", file=sys.stderr)
        return 1

    # Jupyter hides a token it did not make ("token=..."); this one is as fresh as one it makes, so it
    # may show it like its own: its start-up lines then carry the working URL too.
    serverapp.identity_provider.token_generated = True

    def announce():               # runs on the server's loop once the port is bound
        print(f"\n  JupyterLab is running. Open this URL in a browser (the token changes at every start):\n"
              f"\n      {lab_url(serverapp, token)}\n", flush=True)

    serverapp.io_loop.add_callback(announce)
    serverapp.start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
