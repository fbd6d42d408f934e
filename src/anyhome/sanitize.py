"""Strings from outside (the user's text, an LLM reply, a house.json) made safe to print
and to write: no control characters, no terminal escape sequences, no credentials.

One place for these rules, used by the planner (names entering a HouseSpec), the LLM
client (base URLs), the exporters (SVG text and attributes) and the CLI (what it prints).
"""

from __future__ import annotations

import re
from urllib.parse import urlsplit, urlunsplit

ID_PATTERN = r"^[A-Za-z0-9_][A-Za-z0-9_.:-]{0,127}$"
"""The alphabet of room, object, door and window ids in house.json: ASCII letters,
digits and ``_ . : -``, at most 128 characters. Ids become SVG attribute values, file
names of room views and glTF node names, so nothing else is allowed in them."""
ID_RE = re.compile(ID_PATTERN)

# C0 controls except tab and newline, DEL, C1 controls, lone surrogates, bidi
# overrides/isolates (they reorder what a reader sees) and the two XML non-characters.
_CONTROL_RE = re.compile(
    "[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff\u202a-\u202e\u2066-\u2069\ufffe\uffff]"
)
_ESCAPE_SEQ_RE = re.compile(
    r"\x1b(?:\[[0-?]*[ -/]*[@-~]"  # CSI: colours, cursor moves
    r"|\][^\x07\x1b]*(?:\x07|\x1b\\)?"  # OSC: window titles, hyperlinks
    r"|[PX^_][^\x1b]*(?:\x1b\\)?"  # DCS, SOS, PM, APC
    r"|.)",
    re.DOTALL,
)


def clean_text(text: str, newlines: bool = False) -> str:
    """``text`` without terminal escape sequences and control characters.

    Whole escape sequences are removed (``\\x1b]0;title\\x07`` leaves nothing behind),
    then every remaining control character. Tabs are kept; newlines only with
    ``newlines`` (otherwise they become spaces, so a name stays on one line).
    """
    if not isinstance(text, str):
        text = str(text)
    text = _ESCAPE_SEQ_RE.sub("", text)
    if not newlines:
        text = text.replace("\r\n", " ").replace("\n", " ").replace("\r", " ")
    return _CONTROL_RE.sub("", text)


def is_safe_id(value: str) -> bool:
    """True if ``value`` is a valid house.json id (see :data:`ID_PATTERN`)."""
    return isinstance(value, str) and ID_RE.match(value) is not None


def redact_url(url: str) -> str:
    """``url`` with any user and password removed: ``http://u:KEY@host/v1`` becomes
    ``http://host/v1``. Anything that does not parse as a URL is returned cleaned of
    control characters, with an ``@`` prefix cut off as if it were credentials."""
    if not isinstance(url, str):
        return ""
    try:
        parts = urlsplit(url)
        host = parts.hostname or ""
        port = parts.port
    except ValueError:
        return clean_text(url.rsplit("@", 1)[-1])
    if "@" not in parts.netloc:
        return clean_text(url)
    netloc = (f"[{host}]" if ":" in host else host) + (f":{port}" if port else "")
    return clean_text(urlunsplit((parts.scheme, netloc, parts.path, parts.query, parts.fragment)))
