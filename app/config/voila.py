# Voila's configuration for `make app` (loaded with --Voila.config_file_paths=app/config).
# Command-line options win over this file, so the Makefile's variables set the numbers:
#   APP_VISITORS  -> ClassroomKernelManager.max_kernels   (seats; 0: no limit)
#   APP_IDLE      -> MappingKernelManager.cull_idle_timeout (seconds)
# See docs/serving.md and benchmarks/results/classroom.md (where the default seat count comes from).
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from planargeo_classroom import ClassroomKernelManager, turn_away_when_full  # noqa: E402

c = get_config()  # noqa: F821

# one kernel per visitor, at most max_kernels of them; visitor max_kernels + 1 gets a clear page
c.VoilaConfiguration.multi_kernel_manager_class = ClassroomKernelManager
c.VoilaConfiguration.prelaunch_hook = turn_away_when_full
c.ClassroomKernelManager.max_kernels = 8

# a seat comes back after 15 minutes without any activity (no drag, slider, Play), even with the
# page still open: the visitor then reloads the page to get a fresh one
c.MappingKernelManager.cull_idle_timeout = 900
c.MappingKernelManager.cull_interval = 60
c.MappingKernelManager.cull_connected = True
c.MappingKernelManager.cull_busy = False

# when many visitors open the page at once, the kernels' outputs reach Voila late; with the default 4 s
# Voila stops waiting ("Timeout waiting for IOPub output") and the page comes up without some explorers
c.VoilaExecutor.iopub_timeout = 60

# kernel messages sent at once, not held for the browser's delayed acknowledgement (about 40 ms a
# step otherwise): planargeo/widgets/server.py
c.Voila.kernel_websocket_connection_class = "planargeo.widgets.server.PromptKernelConnection"

# never send a traceback to the page
c.VoilaConfiguration.show_tracebacks = False

# the page loads nothing from outside the server: Voila's lab template without its CDN links
# (app/share/jupyter/voila/templates/planargeo); template folders are looked up on JUPYTER_PATH
_share = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "share", "jupyter")
os.environ["JUPYTER_PATH"] = os.pathsep.join(p for p in (_share, os.environ.get("JUPYTER_PATH")) if p)
c.VoilaConfiguration.template = "planargeo"
