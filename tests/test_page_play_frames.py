"""Play in the page: the kernel keeps two frames in flight, and no physics step is skipped.

No browser here: the canvas's messages are caught, and an asyncio loop stands in for the
kernel's (the page's path is driven by tests/browser/test_page_explorers.py).  Each tick the
page sends is answered with a frame, and one more frame follows alone halfway to the next
tick; every frame covers the wall-clock time since the one before (a clock the test
controls), so the time shown is the wall time played, frame by frame.
"""
from __future__ import annotations

import asyncio

from planargeo.errors import PlanargeoError
from planargeo.widgets import ChainExplorer
from planargeo.widgets.canvas import PictureCanvas

FRAME_S = 0.03          # wall seconds each frame's clock advances (set by the test's clock)


def _run(main) -> None:
    """``asyncio.run(main())`` in a thread of its own: its own event loop, whatever loop another
    test (the browser tests' Playwright) left running in this thread."""
    import concurrent.futures

    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        pool.submit(lambda: asyncio.run(main())).result()


def _playing_chain():
    """A chain playing at 1× on a clock that moves FRAME_S seconds per frame, and what its canvas sends."""
    ex = ChainExplorer(display="page", links=3)
    clock = [0.0]
    ex.wall_clock = lambda: clock[0]
    c = ex.canvas
    sent = []
    c.send = lambda m, *a, **k: sent.append(m)
    tick = c.on_tick

    def on_tick():
        clock[0] += FRAME_S
        tick()

    c.on_tick = on_tick
    ex.play_control.playing = True          # linked to the canvas's playing
    return ex, c, sent


def _ticks(c, n: int, gap: float = 0.3) -> None:
    # the extra frame comes at most 0.1 s after its tick (EXTRA_MIN_S..0.1): a gap of 0.3 s leaves
    # it time on a loaded machine before the next tick would cancel it (the clock itself is fake)
    async def run():
        for k in range(n):
            c._on_msg(None, {"type": "tick", "seq": k, "client": "t"}, None)
            await asyncio.sleep(gap)
    _run(run)


def test_each_tick_brings_a_second_frame_and_the_frames_chain():
    ex, c, sent = _playing_chain()
    assert c.playing and ex.shown_values["time (s)"] == 0.0
    v0 = c.version
    _ticks(c, 4)
    kinds = [m["type"] for m in sent if m["type"] in ("ack", "update")]
    assert kinds == ["ack", "update"] * 4
    assert all(m["ok"] for m in sent if m["type"] == "ack")
    updates = [m["update"] if m["type"] == "ack" else m for m in sent]
    # applied in order, each update applies to the version before it
    assert [u["base"] for u in updates] == list(range(v0, v0 + 8))
    assert c.version == v0 + 8 and c.n_extra_frames == 4
    # no physics step skipped: the time shown is the wall time played (the first frame
    # also covers Play's lead of one frame, 1 / play_fps)
    want = 8 * FRAME_S + 1.0 / ex.play_fps
    assert abs(ex.shown_values["time (s)"] - want) < 1e-9
    assert abs(ex.readout_values["t (s)"] - want) < 1e-9


def test_no_second_frame_once_play_stops_or_without_an_event_loop():
    ex, c, sent = _playing_chain()
    ex.play_control.playing = False
    _ticks(c, 2)
    assert [m["type"] for m in sent] == ["ack", "ack"] and c.n_extra_frames == 0
    assert ex.shown_values["time (s)"] == 0.0
    ex.play_control.playing = True
    del sent[:]
    for k in range(3):                      # no running loop: one frame per tick
        c._on_msg(None, {"type": "tick", "seq": k}, None)
    assert [m["type"] for m in sent] == ["ack"] * 3 and c.n_extra_frames == 0


def test_a_refusal_in_the_second_frame_halts_the_page_with_its_reason():
    calls = []

    def on_tick():
        calls.append(1)
        if len(calls) == 2:
            raise PlanargeoError("the motion ends at t = 2 s")

    c = PictureCanvas(on_tick=on_tick)
    sent = []
    c.send = lambda m, *a, **k: sent.append(m)
    c.playing = True
    _ticks(c, 1)
    assert len(calls) == 2
    assert [m["type"] for m in sent] == ["ack", "halt"]
    assert sent[0]["ok"] and sent[1]["message"] == "the motion ends at t = 2 s"


def test_work_ahead_between_frames_gives_the_states_solve_ivp_gives():
    # the chunks computed in slices between frames are scipy's own chunks, bit for bit
    import numpy as np
    from scipy.integrate import solve_ivp

    from planargeo.widgets._motion import Motion

    def rhs(_t, y):                  # a pendulum with a spring: nothing to do with the chain
        return np.array([y[1], -9.81 * np.sin(y[0]) - 2.0 * y[0]])

    sliced, whole = Motion(rhs, [1.0, 0.0], chunk=0.5), Motion(rhs, [1.0, 0.0], chunk=0.5)
    slices = 0
    while sliced.work_ahead(1.2, 1e-9):          # one integrator step per slice, at most
        slices += 1
    assert slices > 3 and sliced.reached == 1.5
    y = np.array([1.0, 0.0])
    for k in range(3):
        r = solve_ivp(rhs, (0.0, 0.5), y, method="DOP853", rtol=1e-9, atol=1e-11, dense_output=True)
        for s in (0.1, 0.25, 0.49):
            t = k * 0.5 + s
            assert np.array_equal(sliced.at(t), r.sol(t - k * 0.5))
            assert np.array_equal(whole.at(t), r.sol(t - k * 0.5))
        y = r.y[:, -1]
        assert np.array_equal(sliced.at((k + 1) * 0.5), y)


def test_a_time_early_in_a_chunk_is_read_before_the_chunk_is_done():
    # Play's first frame waits for the steps up to its time, not for the whole chunk; the states
    # are still scipy's whole-chunk interpolant's, bit for bit
    import numpy as np
    from scipy.integrate import solve_ivp

    from planargeo.widgets._motion import Motion

    calls = [0]

    def rhs(_t, y):
        calls[0] += 1
        return np.array([y[1], -9.81 * np.sin(y[0]) - 2.0 * y[0]])

    whole = solve_ivp(rhs, (0.0, 0.5), [1.0, 0.0], method="DOP853", rtol=1e-9, atol=1e-11,
                      dense_output=True)
    chunk_calls, calls[0] = calls[0], 0
    m = Motion(rhs, [1.0, 0.0], chunk=0.5)
    assert np.array_equal(m.at(0.05), whole.sol(0.05))
    assert m.reached == 0.0 and calls[0] < chunk_calls / 3       # the chunk is not done yet
    for t in (0.02, 0.3, 0.05, 0.49):                          # later and earlier times of the chunk
        assert np.array_equal(m.at(t), whole.sol(t))
    nxt = solve_ivp(rhs, (0.0, 0.5), whole.y[:, -1], method="DOP853", rtol=1e-9, atol=1e-11,
                    dense_output=True)
    assert np.array_equal(m.at(0.6), nxt.sol(0.6 - 0.5)) and m.reached == 0.5
    assert np.array_equal(m.at(0.5), whole.y[:, -1])


def test_play_works_ahead_between_frames_and_shows_the_same_times():
    ex, c, sent = _playing_chain()
    model, q0, qd0, tau = ex.initial_state(ex.values)
    motion = ex.motion_for(model, q0, qd0, tau)
    # the idle slices after each frame compute the chunk after the one shown (a few ticks; more
    # on a loaded machine: each slice is wall time), while the frames stay in the first chunk
    async def run():
        for k in range(12):
            c._on_msg(None, {"type": "tick", "seq": k, "client": "t"}, None)
            await asyncio.sleep(0.05)
            if motion.reached >= 2 * motion.chunk:
                return
    _run(run)
    assert motion.reached >= 2 * motion.chunk and ex.shown_values["time (s)"] < motion.chunk
    fresh = ChainExplorer(display="agg", links=3)
    fresh.set(**{"time (s)": ex.shown_values["time (s)"]})
    assert fresh.readout_values == ex.readout_values


def test_plays_first_frame_is_computed_ahead_once_the_explorer_is_shown():
    # in a kernel, a second after it is shown, the explorer computes Play's first frame and drops
    # it: nothing shown changes, and pressing Play then costs no new evaluation of the dynamics
    from planargeo.widgets.play import WARM_PLAY_S

    async def run():
        ex = ChainExplorer(display="page", links=3)
        sent = []
        ex.canvas.send = lambda m, *a, **k: sent.append(m)
        shown = (dict(ex.values), dict(ex.readout_values), ex.canvas.picture, ex.n_updates)
        await asyncio.sleep(WARM_PLAY_S + 0.3)
        assert (dict(ex.values), dict(ex.readout_values), ex.canvas.picture, ex.n_updates) == shown
        assert not sent
        motion = ex.motion_for(*ex.initial_state(ex.values))
        calls, rhs = [0], motion.rhs

        def counted(t, y):
            calls[0] += 1
            return rhs(t, y)

        motion.rhs = counted
        ex.advance(1)
        assert ex.values["time (s)"] > 0.0 and calls[0] == 0

    _run(run)


def test_the_time_follows_every_frame_and_everything_agrees_when_play_stops():
    """While the page plays, controls and readout reach it at most every PLAY_SYNC_S (a few
    frames); the time slider, the number compared with the picture, follows each picture at once
    (one small message).  When Play stops every held value reaches the page: what it shows is the
    state a fresh explorer of ``ex.values`` shows."""
    ex, c, _sent = _playing_chain()
    log = []          # in the order sent: ("frame", time shown) or (control or "readout", value)
    c.send = lambda m, *a, **k: log.append(("frame", ex.shown_values["time (s)"])
                                           if m["type"] == "update" or m.get("update") else ("other", m))

    def recorder(name):
        return lambda msg, buffers=None: log.append((name, msg["state"].get("value")))

    for k, w in ex.controls.items():
        w._send = recorder(k)
    ex.readout._send = recorder("readout")
    _ticks(c, 4, gap=0.15)                     # faster than Play's syncs: values are held at Stop
    frames = [i for i, (kind, _v) in enumerate(log) if kind == "frame"]
    assert len(frames) == 8
    after = [log[i + 1:j] for i, j in zip(frames, frames[1:] + [len(log)])]
    for i, msgs in zip(frames, after):         # before the next frame: this frame's own time
        assert ("time (s)", log[i][1]) in msgs, (log[i], msgs)
    # the readout waits for Play's sync (the frames come every 0.075 s or so)
    assert sum(1 for msgs in after if "readout" in [kind for kind, _v in msgs]) < len(frames)
    del log[:]
    ex.play_control.playing = False            # Play stops: every held value goes
    last = {kind: v for kind, v in log}
    assert last["time (s)"] == ex.values["time (s)"] and last["readout"] == ex.readout.value
    fresh = ChainExplorer(display="page", **ex.values)
    assert fresh.readout.value == ex.readout.value and fresh.canvas.picture == ex.canvas.picture
    assert {k: w.get_state().get("value") for k, w in fresh.controls.items()} == \
        {k: w.get_state().get("value") for k, w in ex.controls.items()}


def test_a_stop_that_arrives_while_a_frame_is_computed_ends_play_at_that_frame():
    """The page's Stop reaches the kernel while it computes a tick's frame (a slow frame).  In the
    kernel a message that arrived meanwhile is read when the event loop is free, then handed to
    the message loop (a queue, one more turn); the extra frame the tick schedules must not run in
    between: after Stop no frame is added, and the time shown, the readout and the picture are
    the tick's frame's (the last the page is sent)."""
    ex, c, sent = _playing_chain()
    frame_tick = c.on_tick

    async def run():
        loop = asyncio.get_running_loop()
        shell = asyncio.Queue()               # the kernel's message loop: one message at a time

        async def dispatch():
            while True:
                handle = await shell.get()
                handle()

        consumer = asyncio.create_task(dispatch())

        def stop():
            ex.play_control.playing = False   # the Play button's message: playing off

        def slow_tick():
            frame_tick()
            loop.call_soon(shell.put_nowait, stop)      # the Stop that arrived meanwhile, read now

        c.on_tick = slow_tick
        shell.put_nowait(lambda: c._on_msg(None, {"type": "tick", "seq": 0, "client": "t"}, None))
        await asyncio.sleep(0.3)
        consumer.cancel()

    _run(run)
    assert not ex.play_control.playing and not c.playing
    frames = [m for m in sent if m["type"] == "update" or m.get("update")]
    assert [m["type"] for m in sent] == ["ack"] and len(frames) == 1, [m["type"] for m in sent]
    assert c.n_extra_frames == 0
    # one frame of FRAME_S wall seconds (and Play's lead of one frame) at 1×
    want = FRAME_S + 1.0 / ex.play_fps
    assert abs(ex.shown_values["time (s)"] - want) < 1e-9
    assert abs(ex.readout_values["t (s)"] - want) < 1e-9
    fresh = ChainExplorer(display="page", links=3, **{"time (s)": ex.shown_values["time (s)"]})
    assert fresh.canvas.picture == ex.canvas.picture
