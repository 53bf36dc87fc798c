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
#: Unless the caller gives their own: kernel messages sent at once (planargeo.widgets.server).
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


def make_server(argv: list[str], token: str):
    """JupyterLab's server as ``make lab`` runs it (not started): :data:`PROMPT`, ``argv``,
    :data:`FORCED` and ``token``, and the tab's busy icon off (JupyterLab swaps and fetches it
    twice per step: :func:`planargeo.widgets.server.quiet_page_config`)."""
    from jupyterlab.labapp import LabApp

    from planargeo.widgets.server import quiet_page_config

    # the caller's own connection class wins (Jupyter refuses an option given twice)
    own = any(a.split("=", 1)[0].lstrip("-") == PROMPT.split("=", 1)[0].lstrip("-") for a in argv)
    first = [] if own else [PROMPT]
    serverapp = LabApp.initialize_server(argv=[*first, *argv, *FORCED, f"--IdentityProvider.token={token}"])
    serverapp.web_app.settings["page_config_hook"] = quiet_page_config
    return serverapp


def main(argv: list[str]) -> int:
    for a in argv:
        key = a.split("=", 1)[0].lstrip("-").lower()
        if key == "ip" or key.endswith((".ip", "token", ".allow_remote_access")):
            print(f"make lab: {a.split('=', 1)[0]} is set by scripts/lab.py (127.0.0.1 only, a fresh token at "
                  "every start) and cannot be changed", file=sys.stderr)
            return 2
    token = secrets.token_hex(24)
    serverapp = make_server(argv, token)
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
