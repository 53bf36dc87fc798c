"""Jupyter server settings that send the explorers' messages at once (issue 21): TCP_NODELAY on the
kernel websocket (:class:`PromptKernelConnection`, without it a small reply waits ~40 ms for the
browser's delayed acknowledgement) and JupyterLab's busy tab icon off (:func:`quiet_page_config`).
``make lab`` and ``make app`` use them; ``docs/serving.md`` has the configuration and measurements.
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
