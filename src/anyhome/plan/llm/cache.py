"""Replies of the LLM kept on disk, so a rerun with the same inputs makes no calls.

A reply is keyed by the SHA-256 of (base URL, model, messages, schema, sampling
settings) and stored as ``<dir>/<key[:2]>/<key>.json`` with its token usage and
latency, written atomically. ``servers.json`` in the same folder remembers, per base
URL, the structured-output mode the server accepts and the model it serves.

Base URLs are recorded and hashed without their credentials (``user:password@``), and
entries are written as ASCII JSON, so no file here holds a password or a raw control
character. An entry larger than :data:`MAX_ENTRY_BYTES` is not read.
"""

from __future__ import annotations

import hashlib
import json
import logging
import threading
from pathlib import Path
from typing import Any

from anyhome.house import atomic_write_text
from anyhome.sanitize import redact_url

log = logging.getLogger(__name__)

SERVERS_FILE = "servers.json"
MAX_ENTRY_BYTES = 8 * 1024 * 1024
"""A cache entry (or servers.json) larger than this is ignored: no reply is that large."""


def _server_key(base_url: str) -> str:
    return redact_url(base_url).rstrip("/")


def request_key(base_url: str, model: str, messages: list[dict[str, str]], schema: dict[str, Any], sampling: dict[str, Any]) -> str:
    blob = json.dumps(
        {"base_url": _server_key(base_url), "model": model, "messages": messages, "schema": schema, "sampling": sampling},
        sort_keys=True, ensure_ascii=False, separators=(",", ":"),
    )  # fmt: skip
    return hashlib.sha256(blob.encode("utf-8", "surrogatepass")).hexdigest()


class ReplyCache:
    """A folder of cached replies; ``enabled=False`` reads and writes nothing."""

    def __init__(self, root: Path, enabled: bool = True) -> None:
        self.root = Path(root)
        self.enabled = enabled
        self._lock = threading.Lock()

    def _path(self, key: str) -> Path:
        return self.root / key[:2] / f"{key}.json"

    def get(self, key: str) -> dict[str, Any] | None:
        if not self.enabled:
            return None
        path = self._path(key)
        try:
            if path.stat().st_size > MAX_ENTRY_BYTES:
                log.warning("ignoring oversized cache entry %s", path)
                return None
            entry = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            return None
        except (OSError, ValueError, RecursionError) as e:  # a damaged entry is a miss, not a failure
            log.warning("ignoring unreadable cache entry %s: %s", path, type(e).__name__)
            return None
        return entry if isinstance(entry, dict) and isinstance(entry.get("content"), str) else None

    def put(self, key: str, entry: dict[str, Any]) -> None:
        if not self.enabled:
            return
        path = self._path(key)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            atomic_write_text(path, json.dumps(entry, ensure_ascii=True, indent=1) + "\n")
        except OSError as e:  # a cache that cannot be written costs calls, not the run
            log.warning("cannot write LLM cache entry %s: %s", path, e)

    # ------------------------------------------------------------ server notes
    def _servers(self) -> dict[str, Any]:
        path = self.root / SERVERS_FILE
        try:
            if path.stat().st_size > MAX_ENTRY_BYTES:
                return {}
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError, RecursionError):
            return {}
        return data if isinstance(data, dict) else {}

    def server_note(self, base_url: str) -> dict[str, Any]:
        """What was learnt about a server (``mode``, ``model``); read even with the cache off."""
        note = self._servers().get(_server_key(base_url), {})
        return note if isinstance(note, dict) else {}

    def remember_server(self, base_url: str, **note: Any) -> None:
        with self._lock:
            data = self._servers()
            key = _server_key(base_url)
            merged = {**data.get(key, {}), **note}
            if data.get(key) == merged:
                return
            data[key] = merged
            try:
                self.root.mkdir(parents=True, exist_ok=True)
                atomic_write_text(self.root / SERVERS_FILE, json.dumps(data, indent=1, sort_keys=True, ensure_ascii=True) + "\n")
            except OSError as e:
                log.warning("cannot write %s: %s", self.root / SERVERS_FILE, e)
