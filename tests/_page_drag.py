"""A drag driven as canvas.js drives it, for kernel-side tests (no browser).

The pointer's pixel is turned into data through the box of the picture the page holds at that
moment (canvas.js ``dataOf``), one ``drag`` message per move, a ``release`` at the end.
"""
from __future__ import annotations


def page_drag(ex, name: str, dx_px: float, dy_px: float, steps: int):
    """Drag handle ``name`` of explorer ``ex`` by ``(dx_px, dy_px)`` pixels (y down) in ``steps`` moves.

    Returns ``(box, moves, aimed)``: the picture's box when the drag began; per move ``((x, y), reply,
    box, values)`` -- the data point under the pointer, the canvas's reply, the picture's box and the
    explorer's values after it; and the data point the pointer ended over, in the first box.  The
    release is sent and must be taken.
    """
    c = ex.canvas
    W, H = c.picture["size"]
    ml, mr, mt, mb = c.picture["margin"]
    pw, ph = W - ml - mr, H - mt - mb

    def data_of(px, py, b):
        return b[0] + px / (pw / (b[1] - b[0])), b[2] + (ph - py) / (ph / (b[3] - b[2]))

    b0 = tuple(c.picture["box"])
    x0, y0 = ex.handle_position(name)
    px0 = (x0 - b0[0]) * pw / (b0[1] - b0[0])
    py0 = ph - (y0 - b0[2]) * ph / (b0[3] - b0[2])
    moves = []
    for k in range(1, steps + 1):
        x, y = data_of(px0 + dx_px * k / steps, py0 + dy_px * k / steps, c.picture["box"])
        reply = c.handle_message({"type": "drag", "id": name, "x": x, "y": y, "seq": k})
        moves.append(((x, y), reply, tuple(c.picture["box"]), dict(ex.values)))
    assert c.handle_message({"type": "release", "id": name, "seq": steps + 1}) == (True, "")
    return b0, moves, data_of(px0 + dx_px, py0 + dy_px, b0)
