"""Jupyter server setting that sends the explorers' messages at once (issue 21).

Each drag or slider step is one small request from the page and a few small replies. Jupyter's
kernel websockets keep Nagle's algorithm on: a small reply written while the previous one is not yet
acknowledged waits for the browser's delayed acknowledgement, about 40 ms on Linux. Measured in
JupyterLab on the 10-link chain (``benchmarks/page_ab.py``): the empty round trip went from 54 to
19–28 ms and a drag step from 67–69 to 51–53 ms with the delay off.

``make lab`` and ``make app`` use it. For a Jupyter server of your own, add to its configuration
(``jupyter_server_config.py``)::

    c.ServerApp.kernel_websocket_connection_class = (
        "planargeo.widgets.server.PromptKernelConnection")

and for Voila, ``c.Voila.kernel_websocket_connection_class`` likewise.

JupyterLab also swaps the browser tab's icon at every busy and idle message of the kernel, so twice
per step, and fetches the new icon each time: :func:`quiet_page_config` switches that plugin off
(:data:`QUIET_LAB`), and ``make lab`` uses it. Measured the same way: the empty round trip went from
20 to 16 ms and a drag step from 46 to 39 ms. The kernel's state still shows in the notebook's
toolbar and status bar.
"""
from __future__ import annotations

from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection

__all__ = ["PromptKernelConnection", "QUIET_LAB", "quiet_page_config"]

#: The JupyterLab plugins :func:`quiet_page_config` switches off: the tab's busy icon.
QUIET_LAB = ("@jupyterlab/application-extension:faviconbusy",)


class PromptKernelConnection(ZMQChannelsWebsocketConnection):
    """Jupyter's kernel websocket connection with TCP_NODELAY set on the socket.

    Parameters
    ----------
    **kwargs
        As for Jupyter's ``ZMQChannelsWebsocketConnection`` (``parent``, ``websocket_handler``,
        ``config``); the server makes it.
    """

    def connect(self):
        """Switch Nagle's algorithm off for this websocket, then connect as Jupyter does.

        Returns
        -------
        asyncio.Future or None
            What Jupyter's ``connect`` returns.
        """
        self.websocket_handler.set_nodelay(True)
        return super().connect()


def quiet_page_config(handler, page_config: dict) -> dict:
    """JupyterLab's page configuration with the plugins of :data:`QUIET_LAB` switched off.

    A ``page_config_hook`` of JupyterLab's server (its web application's settings, or
    ``c.ServerApp.tornado_settings = {"page_config_hook": quiet_page_config}``).

    Parameters
    ----------
    handler : tornado.web.RequestHandler
        The page's handler (unused).
    page_config : dict
        The page's configuration; its ``disabledExtensions`` is a list of plugin ids.

    Returns
    -------
    dict
        ``page_config``, with :data:`QUIET_LAB` added to ``disabledExtensions``.

    Examples
    --------
    >>> quiet_page_config(None, {"disabledExtensions": ["x"]})["disabledExtensions"]
    ['x', '@jupyterlab/application-extension:faviconbusy']
    """
    off = list(page_config.get("disabledExtensions") or [])
    page_config["disabledExtensions"] = off + [p for p in QUIET_LAB if p not in off]
    return page_config
