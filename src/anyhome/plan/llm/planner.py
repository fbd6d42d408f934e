"""The LLM planner: any OpenAI-compatible model plans the house in the paper's stages.

Stages (prompt templates in ``anyhome/plan/prompts/``):

1. ``program``: the rooms (open-vocabulary name mapped to a functional type, area) and
   the bubble diagram (connections, entrance);
2. ``furniture``, one request per room, concurrently: furniture groups with an anchor,
   members, placement rules and sizes in meters;
3. ``ornaments``, one request per room: small objects on the furniture and the walls;
4. ``appearance`` (asked together with stage 2): style, palette, material words.

Every reply is parsed, validated against its schema (:mod:`.schemas`) and the plan's
sanity rules (:mod:`.checks`). An invalid reply gets one repair request quoting the
errors; still invalid, or the server down or slow, and the offline planner fills that
stage, with a warning. The plan records where each stage came from, the token usage,
the requests and their latency (``HouseSpec.provenance``, written to house.json).

Nothing from the server reaches the plan, the warnings or the provenance raw: its
strings are cleaned of control characters and escape sequences at the boundary
(:mod:`.schemas`), errors and kept replies are cleaned and cut to a bounded length, and
a reply the client rejects (too large, not a chat answer) only costs its stage.
"""

from __future__ import annotations

import logging
import math
import re
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from pydantic import BaseModel, ValidationError

from anyhome.house import ROOM_TYPES
from anyhome.plan.appearance import style_keys
from anyhome.plan.kb import KnowledgeBase
from anyhome.plan.kbview import resolve
from anyhome.plan.llm import checks, prompts
from anyhome.plan.llm.cache import ReplyCache
from anyhome.plan.llm.client import LLMClient, Unavailable, parse_json
from anyhome.plan.llm.config import LLMConfig
from anyhome.plan.llm.schemas import (
    MAX_PALETTE,
    AppearanceReply,
    FurnitureReply,
    ItemReply,
    OrnamentsReply,
    ProgramReply,
    json_schema,
    max_groups,
    max_ornaments,
)
from anyhome.plan.offline import (
    FloorplanStage,
    OfflinePlanner,
    fallback_room,
    item_spec,
    offline_look,
)
from anyhome.plan.spec import MAX_ROOMS, RELATIVE_RULES, GroupSpec, HouseSpec, RoomSpec, kb_context
from anyhome.sanitize import clean_text

log = logging.getLogger(__name__)

MAX_ERRORS_QUOTED = 8
"""Errors quoted in a repair request."""
MAX_KEPT_REPLY_CHARS = 4096
"""Most characters of a reply kept in the provenance (its JSON when that is shorter
serialized, else the start of its text)."""
MAX_ERROR_CHARS = 300
"""Longest error line (quoted in a repair request, a warning and the provenance)."""
MAX_ECHO_CHARS = 16 * 1024
"""Most characters of an invalid reply sent back in its repair request."""
STAGE_MAX_TOKENS = {"program": 600, "furniture": 1100, "ornaments": 500, "appearance": 500}
"""Tokens one stage's reply may take (capped by the configured max tokens)."""


FloorplanCheck = Callable[[HouseSpec], list[str]]
"""``check(spec)``: why the floorplan stage cannot lay out the spec's rooms ([] if it can)."""


@dataclass
class StageRecord:
    """Where one stage's plan came from; written to house.json (no cache flags: a rerun
    served from the cache writes the same record)."""

    stage: str
    source: str = "offline"  # "llm", "llm_repaired" or "offline"
    requests: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    latency_s: float = 0.0
    errors: list[str] = field(default_factory=list)
    reply: Any = None  # the last reply: its JSON, else its text (cleaned, at most MAX_KEPT_REPLY_CHARS)

    def to_json(self) -> dict[str, Any]:
        return {
            "stage": self.stage, "source": self.source, "requests": self.requests,
            "prompt_tokens": self.prompt_tokens, "completion_tokens": self.completion_tokens,
            "latency_s": round(self.latency_s, 3), "errors": self.errors, "reply": self.reply,
        }  # fmt: skip


def _cleaned(node: Any) -> Any:
    """A parsed reply with every string (keys too) cleaned of control characters."""
    if isinstance(node, str):
        return clean_text(node, newlines=True)
    if isinstance(node, dict):
        return {clean_text(str(k)): _cleaned(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_cleaned(v) for v in node]
    if isinstance(node, float) and not math.isfinite(node):
        return str(node)  # house.json holds no bare NaN or Infinity
    return node


def _kept_reply(content: str) -> Any:
    """What the provenance keeps of a reply: bounded, cleaned."""
    head = content[: MAX_KEPT_REPLY_CHARS + 1]
    if len(content) <= MAX_KEPT_REPLY_CHARS:
        try:
            return _cleaned(parse_json(content))
        except (ValueError, RecursionError):
            pass
    text = clean_text(head, newlines=True)
    return text[:MAX_KEPT_REPLY_CHARS] + (" ..." if len(content) > MAX_KEPT_REPLY_CHARS else "")


def _error_line(text: str) -> str:
    text = clean_text(text)
    return text if len(text) <= MAX_ERROR_CHARS else text[: MAX_ERROR_CHARS - 3] + "..."


def _echo(content: str) -> str:
    """An invalid reply as sent back in the repair request: at most its start."""
    return content if len(content) <= MAX_ECHO_CHARS else content[:MAX_ECHO_CHARS] + "\n[... cut]"


def _slug(text: str) -> str:
    return "_".join(re.findall(r"[a-z0-9]+", text.lower())) or "item"


def _pydantic_errors(e: ValidationError) -> list[str]:
    out = []
    for err in e.errors()[:MAX_ERRORS_QUOTED]:
        where = ".".join(str(p) for p in err["loc"]) or "reply"
        out.append(_error_line(f"{where}: {err['msg']}"))
    return out


class LLMPlanner:
    """Plans with a chat model; see the module doc. ``config`` from :func:`load_config`."""

    name = "llm"

    def __init__(self, config: LLMConfig, floorplan_check: FloorplanCheck | None = None,
                 kb: KnowledgeBase | None = None, floorplan: FloorplanStage | None = None) -> None:
        """``floorplan_check(spec)`` lists why a program's rooms and connections cannot be
        laid out ([] when they can); the program reply is checked with it too. None skips
        that check: whoever builds the planner passes the floorplan stage's check (see
        ``anyhome.plan.get_planner`` and ``anyhome.floorplan.floorplan_errors``). ``kb``:
        the knowledge base the offline fallbacks and the reply checks read (None: the one in
        force). ``floorplan``: the floorplan stage the offline fallback meets stated totals
        with (see :class:`~anyhome.plan.offline.OfflinePlanner`)."""
        self.config = config
        self.floorplan = floorplan
        self.kb = resolve(kb)
        self.floorplan_check = floorplan_check
        self.client: LLMClient | None = None  # of the last run: usage for the summary

    # ------------------------------------------------------------------ one stage
    def _ask(self, label: str, stage: str, messages: list[dict[str, str]], model: type[BaseModel],
             check: Callable[[Any], list[str]], seed: int, warnings: list[str],
             schema: dict[str, Any] | None = None) -> tuple[Any, StageRecord]:  # fmt: skip
        """The validated reply of one stage (None: fall back) and its record."""
        assert self.client is not None
        rec = StageRecord(label)
        schema = schema or json_schema(stage)

        def validate(content: str) -> tuple[Any, list[str]]:
            try:
                obj = model.model_validate(parse_json(content))
            except ValueError as e:  # ValidationError is a ValueError
                return None, _pydantic_errors(e) if isinstance(e, ValidationError) else [_error_line(str(e))]
            return obj, [_error_line(e) for e in check(obj)]

        try:
            for attempt in range(2):
                reply = self.client.chat_json(messages, schema, stage, seed, STAGE_MAX_TOKENS[stage])
                rec.requests += 1
                rec.prompt_tokens += reply.prompt_tokens
                rec.completion_tokens += reply.completion_tokens
                rec.latency_s += reply.latency_s
                rec.reply = _kept_reply(reply.content)
                obj, errors = validate(reply.content)
                if not errors:
                    rec.source = "llm" if attempt == 0 else "llm_repaired"
                    return obj, rec
                rec.errors = errors[:MAX_ERRORS_QUOTED]
                quoted = "\n".join(f"- {e}" for e in rec.errors)
                messages = [*messages, {"role": "assistant", "content": _echo(reply.content)},
                            {"role": "user", "content": prompts.fill("repair", errors=quoted)}]  # fmt: skip
            warnings.append(f"LLM {label}: the reply was still invalid after one repair ({rec.errors[0]}); the offline planner filled it")
        except Unavailable as e:
            rec.errors = [_error_line(str(e))]
            warnings.append(f"LLM {label}: {rec.errors[0]}; the offline planner filled it")
        return None, rec

    def _program_check(self, reply: ProgramReply) -> list[str]:
        """The sanity rules, then whether the floorplan stage can lay the rooms out."""
        errors = checks.check_program(reply, self.kb)
        if errors or self.floorplan_check is None:
            return errors
        rooms = [RoomSpec(id=r.id, name=r.name, type=r.type, area_m2=r.area_m2) for r in reply.rooms]
        spec = HouseSpec.model_validate(dict(prompt="", rooms=rooms, connections=_connections(reply)), context=kb_context(self.kb))
        return [f"these rooms and connections cannot be laid out as a floorplan: {e}"
                for e in self.floorplan_check(spec)]

    # ------------------------------------------------------------------ the plan
    def plan(self, text: str, rng: np.random.Generator) -> HouseSpec:
        offline = OfflinePlanner(self.kb, self.floorplan).plan(text, rng)  # the fallback of every stage (raises on empty text)
        seed = int(rng.integers(2**31 - 1))
        look = offline_look(self.kb, text, np.random.default_rng(seed))
        self.client = LLMClient(self.config, ReplyCache(self.config.cache_dir, enabled=self.config.cache))
        warnings: list[str] = []
        records: list[StageRecord] = []
        try:
            model_name = self.client.model()
        except Unavailable as e:
            why = _error_line(str(e))
            warnings.append(f"LLM: {why}; the offline planner planned the whole house")
            labels = ["program", *(f"furniture:{r.id}" for r in offline.rooms), "appearance", *(f"ornaments:{r.id}" for r in offline.rooms)]
            records = [StageRecord(label, errors=[why]) for label in labels]
            return self._finish(offline, offline.warnings + warnings, records, self.config.model or "")

        # 1. program and bubble diagram
        types = ", ".join(ROOM_TYPES)
        msgs = prompts.messages("program", text=text, max_rooms=MAX_ROOMS, types=types)
        program, rec = self._ask("program", "program", msgs, ProgramReply, self._program_check, seed, warnings)
        records.append(rec)
        if program is None:
            rooms = list(offline.rooms)
            connections = list(offline.connections)
            building = offline.building
            warnings[:0] = offline.warnings
        else:
            building = program.building.strip().lower()
            rooms = [fallback_room(self.kb, r.name, r.type, round(r.area_m2, 2), r.id, look, np.random.default_rng([seed, i]))
                     for i, r in enumerate(program.rooms)]  # fmt: skip
            connections = _connections(program)

        # 2 + 4. furniture per room and the appearance, concurrently
        room_list = "; ".join(f"{r.id} ({r.name}, {r.type})" for r in rooms)
        jobs: list[tuple] = []
        for r in rooms:
            m = prompts.messages("furniture", text=text, building=building, name=r.name, type=r.type.replace("_", " "),
                                 area_m2=f"{r.area_m2:g}", max_groups=max_groups(r.area_m2))  # fmt: skip
            jobs.append((f"furniture:{r.id}", "furniture", m, FurnitureReply, _area_check(r.area_m2),
                         json_schema("furniture", max_items=max_groups(r.area_m2))))
        ids = {r.id for r in rooms}
        m = prompts.messages("appearance", text=text, building=building, rooms=room_list, max_palette=MAX_PALETTE)
        jobs.append(("appearance", "appearance", m, AppearanceReply, lambda a: checks.check_appearance(ids, [x.id for x in a.rooms]),
                     json_schema("appearance", room_ids=[r.id for r in rooms])))  # fmt: skip
        results = self._run_all(jobs, seed, warnings)
        appearance, appearance_rec = results[-1]
        look = _apply_look(look, appearance)
        for r_i, (obj, rec) in enumerate(results[:-1]):
            records.append(rec)
            if obj is not None:
                rooms[r_i] = replace_groups(self.kb, rooms[r_i], obj, look, np.random.default_rng([seed, 100 + r_i]))
        records.append(appearance_rec)

        # 3. ornaments per room, once the furniture is known
        jobs = []
        for r in rooms:
            names = _furniture_names(r.groups)
            pieces = sorted({it.name for g in r.groups for it in [g.anchor, *g.members]})
            m = prompts.messages("ornaments", text=text, building=building, name=r.name, type=r.type.replace("_", " "),
                                 furniture=", ".join(pieces) or "none", max_ornaments=max_ornaments(r.area_m2))  # fmt: skip
            jobs.append((f"ornaments:{r.id}", "ornaments", m, OrnamentsReply, _ornament_check(names),
                         json_schema("ornaments", targets=pieces, max_items=max_ornaments(r.area_m2))))
        for r_i, (obj, rec) in enumerate(self._run_all(jobs, seed, warnings)):
            records.append(rec)
            if obj is not None:
                rooms[r_i] = replace_ornaments(self.kb, rooms[r_i], obj, look, np.random.default_rng([seed, 200 + r_i]))
        if appearance is not None:
            rooms = [_dress(r, appearance) for r in rooms]
        spec = HouseSpec.model_validate(dict(
            prompt=text, building=building or offline.building,
            style=appearance.style if appearance is not None else offline.style,
            styles=(style_keys(appearance.style, kb=self.kb) or offline.styles) if appearance is not None else offline.styles,
            palette=list(appearance.palette) if appearance is not None else offline.palette,
            rooms=rooms, connections=connections, warnings=warnings,
        ), context=kb_context(self.kb))  # fmt: skip
        return self._finish(spec, spec.warnings, records, model_name)

    def _run_all(self, jobs: list[tuple], seed: int, warnings: list[str]) -> list[tuple[Any, StageRecord]]:
        """Run stage requests concurrently; results and warnings in job order."""
        per_job: list[list[str]] = [[] for _ in jobs]

        def run(i: int) -> tuple[Any, StageRecord]:
            label, stage, msgs, model, check, schema = jobs[i]
            return self._ask(label, stage, msgs, model, check, seed, per_job[i], schema)

        with ThreadPoolExecutor(max_workers=self.config.concurrency) as pool:
            results = list(pool.map(run, range(len(jobs))))
        warnings.extend(w for ws in per_job for w in ws)
        return results

    def _finish(self, spec: HouseSpec, warnings: list[str], records: list[StageRecord], model_name: str) -> HouseSpec:
        warnings = list(dict.fromkeys(warnings))
        stages = [r.to_json() for r in records]
        provenance = {
            "planner": "llm",
            "llm": {**self.config.public(), "model": model_name},
            "stages": stages,
            "totals": {
                "requests": sum(s["requests"] for s in stages),
                "prompt_tokens": sum(s["prompt_tokens"] for s in stages),
                "completion_tokens": sum(s["completion_tokens"] for s in stages),
                "latency_s": round(sum(s["latency_s"] for s in stages), 3),
                "stages_from_llm": sum(s["source"] != "offline" for s in stages),
                "stages_from_offline": sum(s["source"] == "offline" for s in stages),
            },
        }
        return spec.model_copy(update={"warnings": warnings, "provenance": provenance})


# ---------------------------------------------------------------------- helpers
def _area_check(area_m2: float) -> Callable[[FurnitureReply], list[str]]:
    return lambda reply: checks.check_furniture(reply, area_m2)


def _ornament_check(names: set[str]) -> Callable[[OrnamentsReply], list[str]]:
    return lambda reply: checks.check_ornaments(reply, names)


def _furniture_names(groups: list[GroupSpec]) -> set[str]:
    """Lower-case names and categories of the groups' items (what an ornament may target)."""
    return {x.lower() for g in groups for it in [g.anchor, *g.members] for x in (it.name, it.category)}


def _connections(program: ProgramReply) -> list[tuple[str, str]]:
    seen: set[frozenset[str]] = set()
    out: list[tuple[str, str]] = []
    for a, b in program.connections:
        if "outside" in (a, b):
            continue
        key = frozenset((a, b))
        if key not in seen:
            seen.add(key)
            out.append((a, b))
    return [*out, (program.entrance, "outside")]


def replace_groups(kb: KnowledgeBase, room: RoomSpec, reply: FurnitureReply, look: Any, rng: np.random.Generator) -> RoomSpec:
    """The room with the model's furniture groups (and its ornaments loosened to match)."""
    groups: list[GroupSpec] = []
    used: dict[str, int] = {}
    for priority, g in enumerate(reply.groups):
        anchor = g.anchor
        by_key = {anchor.name.lower(): anchor.name, anchor.category.lower(): anchor.name}
        members = []
        for m in g.members:
            target = None
            if m.rule in RELATIVE_RULES and m.target and by_key.get(m.target.lower(), anchor.name) != anchor.name:
                target = by_key[m.target.lower()]
            members.append(item_spec(kb, _item_data(m, target), look, rng))
            by_key.setdefault(m.name.lower(), m.name)
            by_key.setdefault(m.category.lower(), m.name)
        base = _slug(g.name)
        used[base] = used.get(base, 0) + 1
        groups.append(GroupSpec(
            name=base if used[base] == 1 else f"{base}_{used[base]}",
            anchor=item_spec(kb, _item_data(anchor, None), look, rng), members=members,
            arrangement=g.arrangement, repeat=g.repeat, priority=priority,
        ))  # fmt: skip
    names = _furniture_names(groups)
    ornaments = [o if o.target is None or o.target.lower() in names else o.model_copy(update={"target": None}) for o in room.ornaments]
    return room.model_copy(update={"groups": groups, "ornaments": ornaments})


def _item_data(it: ItemReply, target: str | None) -> dict[str, Any]:
    return {
        "name": it.name.strip(), "category": _slug(it.category), "size_m": tuple(round(float(s), 3) for s in it.size_m),
        "rule": it.rule, "target": target, "count": it.count, "params": it.given_params(),
    }  # fmt: skip


def replace_ornaments(kb: KnowledgeBase, room: RoomSpec, reply: OrnamentsReply, look: Any, rng: np.random.Generator) -> RoomSpec:
    ornaments = [item_spec(kb, _item_data(o, o.target.strip() or None), look, rng) for o in reply.ornaments]
    return room.model_copy(update={"ornaments": ornaments})


def _apply_look(look: Any, appearance: AppearanceReply | None) -> Any:
    if appearance is None:
        return look
    return replace(look, describe=appearance.style, palette=list(appearance.palette), furniture=appearance.furniture)


def _dress(room: RoomSpec, appearance: AppearanceReply) -> RoomSpec:
    entry = next((x for x in appearance.rooms if x.id == room.id), None)
    update: dict[str, Any] = {"style": appearance.style}
    if entry is not None:
        update["materials"] = {"floor": entry.floor, "walls": entry.walls, "ceiling": entry.ceiling}
    return room.model_copy(update=update)
