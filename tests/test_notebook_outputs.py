"""The outputs stored in the notebooks are what a fresh, deterministic run produces.

Each notebook is re-executed the way ``make notebooks`` stores it (notebooks/run_all.py: fresh kernel,
inline PNG figures, fixed seeds, no timings) and its outputs are compared with the committed ones,
normalised: text exactly (memory addresses and widget model ids masked, execution counts ignored),
images pixel by pixel (root-mean-square difference at most 2e-3 of full scale), cells tagged
``output-varies`` by the kinds of their outputs only.  A difference means the code or a lesson
changed without ``make notebooks``: run it and commit the notebooks.
"""
import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("run_all", ROOT / "notebooks" / "run_all.py")
run_all = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(run_all)

nbformat = pytest.importorskip("nbformat")
pytest.importorskip("nbclient")


@pytest.mark.slow
@pytest.mark.parametrize("path", run_all.notebook_paths(), ids=lambda p: p.name)
def test_stored_outputs_are_a_fresh_run(path):
    stored = nbformat.read(path, as_version=4)
    fresh, seconds, skipped = run_all.execute(path)
    problems = run_all.differences(stored, fresh)
    assert not problems, f"{path.name} (run `make notebooks`):\n" + "\n".join(problems[:20])


def test_the_comparison_sees_a_changed_number_and_a_changed_picture():
    """The normalisation masks ids and counts, not content."""
    from nbformat.v4 import new_code_cell, new_notebook, new_output

    import base64
    import io

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def png(y):
        fig, ax = plt.subplots(figsize=(2, 2))
        ax.plot([0, 1], [0, y])
        buf = io.BytesIO()
        fig.savefig(buf, format="png")
        plt.close(fig)
        return base64.b64encode(buf.getvalue()).decode()

    def nb(text, y, model):
        cell = new_code_cell("x")
        cell.execution_count = 7
        cell.outputs = [new_output("stream", name="stdout", text=text),
                        new_output("display_data", data={"image/png": png(y), "text/plain": "<Figure>"}),
                        new_output("execute_result", execution_count=7, data={
                            "application/vnd.jupyter.widget-view+json": {"model_id": model, "version_major": 2},
                            "text/plain": f"VBox(object at 0x7f{model[:8]})"})]
        out = new_notebook()
        out.cells = [cell]
        return out

    a = nb("3.0\n", 1.0, "a" * 32)
    assert run_all.differences(a, nb("3.0\n", 1.0, "b" * 32)) == []       # ids and addresses masked
    assert run_all.differences(a, nb("3.1\n", 1.0, "a" * 32))             # a number changed
    assert run_all.differences(a, nb("3.0\n", 0.2, "a" * 32))             # a picture changed
