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
"""
from __future__ import annotations

from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection

__all__ = ["PromptKernelConnection"]


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
