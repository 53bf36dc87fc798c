# Jupyter server config (used by page_ab.py --lab-config-b benchmarks/nodelay_config.py): kernel websockets send each message at once (TCP_NODELAY), not after
# the browser's delayed ACK of the previous one (Nagle's algorithm).
import tornado.websocket as _tw

_write = _tw.WebSocketHandler.write_message


def _write_message(self, message, binary=False):
    if not getattr(self, "_pg_nodelay", False) and self.ws_connection is not None:
        self.set_nodelay(True)
        self._pg_nodelay = True
    return _write(self, message, binary)


_tw.WebSocketHandler.write_message = _write_message
