"""A seat limit for ``make app``: visitor ``max_kernels + 1`` gets a clear page, not a slow machine.

Voila starts one kernel (one Python process holding every explorer) per visitor and has
no limit of its own.  Two pieces, wired in by ``app/config/voila.py``:

* :class:`ClassroomKernelManager` counts seats: running kernels, kernels being started
  and visitors admitted whose kernel has not started yet.  With ``max_kernels`` seats
  taken it refuses to start another kernel (HTTP 503).
* :func:`turn_away_when_full`, Voila's ``prelaunch_hook``, runs before a visitor's page is
  rendered: when every seat is taken it answers with :data:`FULL_PAGE` (HTTP 503,
  ``Retry-After``) and nothing is started; otherwise it takes a seat for that visitor.

Seats come back when a visitor closes the page (Voila's page asks for its kernel to be
shut down; the hook sets the ``_xsrf`` cookie that request needs) or when
the kernel is culled after ``MappingKernelManager.cull_idle_timeout`` seconds without
activity (set in ``voila.py``; ``make app APP_IDLE=...``).
"""
from __future__ import annotations

import collections
import time

from jupyter_server.services.kernels.kernelmanager import AsyncMappingKernelManager
from tornado import web
from traitlets import Float, Int

#: what visitor ``max_kernels + 1`` sees (no script, no external resource)
FULL_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>The class is full</title>
<style>body{{font-family:sans-serif;max-width:36em;margin:4em auto;padding:0 1em;line-height:1.5;color:#222}}
h1{{font-size:1.6em}}</style></head>
<body id="planargeo-class-full">
<h1>The class is full</h1>
<p>This computer is already serving the explorers to {seats}, as many as it can hold
while keeping them responsive.</p>
<p>Please wait a minute and reload this page. A seat becomes free when someone closes their
page, or after {idle} of inactivity.</p>
<p>If you are the teacher: the limit is set when the app is started
(<code>make app APP_VISITORS=...</code>); see the guide “Serving the app to a class”.</p>
</body></html>
"""


def _minutes(seconds: float) -> str:
    if seconds <= 0:
        return "a while"
    m = round(seconds / 60)
    return f"{m} minute{'s' if m != 1 else ''}" if m >= 1 else f"{int(seconds)} seconds"


class ClassroomKernelManager(AsyncMappingKernelManager):
    """Voila's kernel manager with at most ``max_kernels`` seats (one kernel per visitor).

    ``max_kernels = 0`` means no limit.  A seat is taken by a running kernel, by a kernel
    being started, and by a visitor admitted by :meth:`admit` whose kernel has not started
    yet (such a reservation lapses after ``admission_timeout`` seconds).
    """

    max_kernels = Int(0, config=True, help="At most this many visitors (kernels) at once; 0: no limit.")
    admission_timeout = Float(120.0, config=True,
                              help="Seconds an admitted visitor's seat is kept until the kernel starts.")

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._admitted: collections.deque[float] = collections.deque()
        self._starting = 0

    def seats_taken(self) -> int:
        """Running kernels, kernels being started and admitted visitors without a kernel yet."""
        now = time.monotonic()
        while self._admitted and now - self._admitted[0] > self.admission_timeout:
            self._admitted.popleft()
        return len(self.list_kernel_ids()) + self._starting + len(self._admitted)

    def full(self) -> bool:
        """Whether every seat is taken (never, with ``max_kernels = 0``)."""
        return self.max_kernels > 0 and self.seats_taken() >= self.max_kernels

    def admit(self) -> bool:
        """Take a seat for a new visitor; ``False`` if every seat is taken."""
        if self.full():
            self.log.warning("The class is full: a visitor was turned away (%d of %d seats taken)",
                             self.seats_taken(), self.max_kernels)
            return False
        if self.max_kernels > 0:
            self._admitted.append(time.monotonic())
        return True

    async def start_kernel(self, *args, **kwargs):
        kernel_id = kwargs.get("kernel_id")
        if kernel_id is not None and kernel_id in self:     # an existing kernel: no new seat
            return await super().start_kernel(*args, **kwargs)
        if self._admitted:                                  # the seat admit() took becomes this start
            self._admitted.popleft()
        elif self.full():                                   # no hook in front of us: refuse here
            raise web.HTTPError(503, "every seat is taken (%d)", self.max_kernels,
                                reason="The class is full")
        self._starting += 1
        try:
            return await super().start_kernel(*args, **kwargs)
        finally:
            self._starting -= 1


def turn_away_when_full(req, notebook, cwd):
    """Voila's ``prelaunch_hook``: answer :data:`FULL_PAGE` (503) when every seat is taken."""
    km = req.kernel_manager
    admit = getattr(km, "admit", None)
    if admit is None or admit():
        # Voila's page asks the server to shut its kernel down when the visitor leaves (a POST
        # carrying the _xsrf cookie); Voila's notebook page never sets that cookie, so the POST is
        # refused (403) and the seat stays taken until culled. Reading the token sets the cookie.
        req.xsrf_token  # noqa: B018
        return notebook
    req.clear()
    req.set_status(503)
    req.set_header("Content-Type", "text/html; charset=utf-8")
    req.set_header("Cache-Control", "no-store")
    req.set_header("Retry-After", "60")
    idle = km.cull_idle_timeout if km.cull_idle_timeout > 0 else 0
    seats = f"{km.max_kernels} visitor{'s' if km.max_kernels != 1 else ''}"
    raise web.Finish(FULL_PAGE.format(seats=seats, idle=_minutes(idle)))
