"""What the stages read from a :class:`~anyhome.plan.kb.KnowledgeBase` passed to them.

The knowledge base is loaded and validated once per run (``knowledge_base()`` of
:mod:`anyhome.plan.knowledge`, or given by the caller) and passed explicitly to the
planner and the assets stage; the functions here derive what they need from it, cached
per knowledge base (two knowledge bases in one process never share a table).
"""

from __future__ import annotations

import functools
from typing import Any

from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.knowledge import Vocabulary, compile_vocabulary


def default() -> KnowledgeBase:
    """The knowledge base in force (shipped files, ``$ANYHOME_KNOWLEDGE_PATH`` and
    ``--knowledge``): what an entry point uses when the caller passes none."""
    from anyhome.plan.knowledge import knowledge_base

    return knowledge_base()


def raw(kb: KnowledgeBase, name: str) -> dict[str, Any]:
    """The merged content of ``<name>.yaml`` in ``kb`` as plain mappings."""
    return kb.raw(name)


@functools.lru_cache(maxsize=8)
def vocabulary(kb: KnowledgeBase) -> Vocabulary:
    """Every phrase of ``kb`` compiled into lookup tables and regular expressions."""
    return compile_vocabulary(kb)


def resolve(kb: KnowledgeBase | None) -> KnowledgeBase:
    """``kb``, or :func:`default` for a caller outside the stages that passed none (a
    test, a tool calling one planner function); the stages always pass theirs."""
    return kb if kb is not None else default()


def is_dwelling(kb: KnowledgeBase, program: str | None) -> bool:
    """Whether ``program`` is one people live in (programs.yaml ``sizes.homes``)."""
    return program in set((kb.raw("programs").get("sizes") or {}).get("homes", []))
