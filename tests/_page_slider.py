"""A model of how the page shows a slider: the updates the kernel sends it, taken in any key order.

A browser's slider (ipywidgets' noUiSlider) may apply the value of one update message before the
range in the same message: a value beyond the range it still has is then pulled to that range's
end, sent back to the kernel, and the rest of the message (e.g. ``disabled``) is not shown.  So a
value is safe only when it fits both the range the page has before the message and after it.
"""
from __future__ import annotations


class PageSlider:
    """Records what the kernel sends a slider and the page's view of it.

    Parameters
    ----------
    slider : ipywidgets IntSlider or FloatSlider
        Its ``_send`` is replaced by the recorder (as ``test_widgets_base`` does).
    """

    def __init__(self, slider):
        self.shown = {k: getattr(slider, k) for k in ("value", "min", "max", "disabled")}
        self.problems: list[str] = []
        slider._send = self._receive

    def _receive(self, msg, buffers=None):
        state = msg.get("state", {}) if msg.get("method") == "update" else {}
        before = dict(self.shown)
        after = {**before, **{k: v for k, v in state.items() if k in before}}
        if "value" in state:
            v = state["value"]
            for name, s in (("before", before), ("after", after)):
                if not s["min"] <= v <= s["max"]:
                    self.problems.append(f"value {v} sent with the range {s['min']}..{s['max']} {name} "
                                         f"the message {state}")
        self.shown = after
