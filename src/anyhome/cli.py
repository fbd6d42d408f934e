"""The ``anyhome`` command line. User-facing output lives here and only here."""

from __future__ import annotations

import argparse
import json
import logging
import os
import sys
import time
from collections import Counter
from pathlib import Path
from typing import TYPE_CHECKING

from shapely.geometry import Polygon

if TYPE_CHECKING:
    from anyhome.plan.kb import KnowledgeBase

from anyhome import __version__
from anyhome.errors import AnyHomeError
from anyhome.house import stand_ins
from anyhome.sanitize import clean_text, redact_url

STAGE_LABELS = {
    "plan": "planning rooms and furniture",
    "floorplan": "solving the floorplan",
    "layout": "placing objects",
    "refine": "refining the layout",
    "assets": "choosing assets",
}
STEP_LABELS = {"write": "[out] writing files", "render": "[render] bird's-eye and room views"}
"""Steps after the stages (write_outputs' progress), printed without a number."""

_open_line = False
"""True while a progress line waits for its time ("[2/5] solving the floorplan ...")."""


def _shown(value: object) -> str:
    """``value`` safe to print: no escape sequences or control characters, and no lone
    surrogates (a path or text from invalid UTF-8 bytes)."""
    return clean_text(str(value))


def _err(msg: str) -> None:
    """Print ``msg`` on stderr on its own line (ending a progress line left open)."""
    global _open_line
    if _open_line:
        print(" failed", file=sys.stderr, flush=True)
        _open_line = False
    print(_shown(msg), file=sys.stderr, flush=True)


class _StageProgress:
    """Prints one line per stage on stderr: ``[2/5] solving the floorplan ... 0.04 s``."""

    def __init__(self, enabled: bool) -> None:
        self.enabled = enabled
        self.order = list(STAGE_LABELS)

    def __call__(self, stage: str, event: str, seconds: float) -> None:
        global _open_line
        if not self.enabled:
            return
        if stage in STEP_LABELS:
            label = STEP_LABELS[stage]
        else:
            k = self.order.index(stage) + 1 if stage in self.order else 0
            label = f"[{k}/{len(self.order)}] {STAGE_LABELS.get(stage, stage)}"
        if event == "start":
            print(f"{label} ...", end="", file=sys.stderr, flush=True)
            _open_line = True
        else:
            print(f" {seconds:.2f} s", file=sys.stderr, flush=True)
            _open_line = False


# ------------------------------------------------------------------ generate
def cmd_generate(args: argparse.Namespace) -> int:
    from anyhome.outdir import check_out
    from anyhome.pipeline import check_text, generate, write_outputs

    # cheap checks first: a bad text, --out or render size costs no generation
    check_text(args.text)
    out = check_out(args.out)
    if args.render:
        _check_render_options(args)
    if not args.no_glb:
        from anyhome.materials.catalog import texture_size_px

        texture_size_px()  # a bad $ANYHOME_TEXTURE_PX is one line, before any work
    if args.embedder:
        from anyhome.plan.embed import ENV_BACKEND, get_embedder

        os.environ[ENV_BACKEND] = args.embedder
        get_embedder()  # fails early, with one line, on an unknown or missing backend
    from anyhome.plan.knowledge import knowledge_base, use_knowledge

    use_knowledge(args.knowledge)
    kb = knowledge_base()  # a bad knowledge file (shipped or the user's) is one line, before any work
    planner = _planner(args, kb)
    stages = _stages(args)
    t0 = time.perf_counter()
    progress = _StageProgress(not args.quiet)
    house = generate(args.text, seed=args.seed, planner=planner, progress=progress, stages=stages, knowledge=kb)
    timings = dict(house.timings_s)
    extra = (lambda folder: _render(house, folder, args)) if args.render else None
    files = write_outputs(house, out, glb=not args.no_glb, svg=not args.no_svg, timings=timings,
                          extra=extra, progress=progress)
    files = [Path(args.out) / f.relative_to(out) for f in files]  # as the user named the folder
    total = time.perf_counter() - t0
    if args.json:
        print(json.dumps({
            "out": str(args.out), "files": [str(f) for f in files], "rooms": len(house.rooms),
            "objects": len(house.objects), "dropped": len(house.dropped),
            "stand_ins": len(stand_ins(house.objects)),
            "warnings": house.warnings, "timings_s": timings, "total_s": total,
            **({"llm": _llm_usage(planner, house)} if args.planner == "llm" else {}),
        }))
    else:
        _print_summary(house, files, timings, total)
        if args.planner == "llm":
            _print_llm(_llm_usage(planner, house))
    return 0


def _stages(args: argparse.Namespace):
    """The generation stages: the defaults, with the asset library of ``--assets``,
    ``$ANYHOME_ASSETS`` or the config file's ``[assets] dir`` indexed here (a missing or
    empty folder is one line, before any work); None without a library."""
    from anyhome.assets.library import folder_in_force, open_library

    folder = folder_in_force(args.assets, args.config)
    if folder is None:
        return None
    from anyhome.stages import Stages, library_assets

    return Stages(assets=library_assets(open_library(folder)))


def _planner(args: argparse.Namespace, kb: KnowledgeBase):
    """The planner object of ``generate`` reading ``kb``; the LLM one from options, env
    and config file."""
    from anyhome.plan import get_planner

    if args.planner != "llm":
        return get_planner(args.planner, kb)  # an unknown name raises the one-line error
    from anyhome.floorplan import floorplan_errors
    from anyhome.plan.llm import LLMPlanner, load_config

    options = {
        "base_url": args.llm_base_url, "model": args.llm_model, "temperature": args.llm_temperature,
        "top_p": args.llm_top_p, "max_tokens": args.llm_max_tokens, "timeout_s": args.llm_timeout,
        "concurrency": args.llm_concurrency, **({"cache": False} if args.no_cache else {}),
    }  # fmt: skip
    return LLMPlanner(load_config(options, config_file=args.config), floorplan_check=floorplan_errors, kb=kb)


def _llm_usage(planner, house) -> dict:
    """What the LLM planner did in this run: made calls and cache hits (not in house.json,
    where a rerun from the cache must write the same file), and the plan's totals."""
    usage = planner.client.usage if planner.client is not None else None
    prov = house.provenance or {}
    return {
        "model": prov.get("llm", {}).get("model"), "base_url": prov.get("llm", {}).get("base_url"),
        "calls": usage.calls if usage else 0, "cache_hits": usage.cache_hits if usage else 0,
        "prompt_tokens": usage.prompt_tokens if usage else 0, "completion_tokens": usage.completion_tokens if usage else 0,
        "call_latency_s": round(usage.latency_s, 3) if usage else 0.0,
        "stages": {s["stage"]: s["source"] for s in prov.get("stages", [])},
    }  # fmt: skip


def _print_llm(u: dict) -> None:
    sources = Counter(u["stages"].values())
    fell = [_shown(k) for k, v in u["stages"].items() if v == "offline"]
    model, url = _shown(u["model"] or "(model unknown)"), _shown(redact_url(str(u["base_url"])))
    print(f"LLM: {model} at {url}: {u['calls']} calls, {u['cache_hits']} from the cache, "
          f"{u['prompt_tokens']} + {u['completion_tokens']} tokens, {u['call_latency_s']:.1f} s in calls")
    print(f"  stages: {sources['llm']} from the LLM, {sources['llm_repaired']} repaired, {sources['offline']} from the offline planner"
          + (f" ({', '.join(fell[:6])}{', ...' if len(fell) > 6 else ''})" if fell else ""))


def _print_summary(house, files, timings: dict[str, float], total: float) -> None:
    per_room = Counter(o.room for o in house.objects)
    print(f"House: {len(house.rooms)} rooms, {len(house.doors)} doors, "
          f"{len(house.windows)} windows, {len(house.objects)} objects  (style: {_shown(house.style)})")
    for room in house.rooms:
        area = Polygon(room.polygon).area
        print(f"  {_shown(room.id):<14} {_shown(room.name):<22} {area:6.1f} m2  {per_room[room.id]:3d} objects")
    if house.dropped:
        print(f"Dropped {len(house.dropped)} item(s) that did not fit:")
        for d in sorted(house.dropped, key=lambda d: not d.key)[:10]:  # asked-for items first
            key = "  [a key item: asked for, or what the room is for]" if d.key else ""
            print(f"  {_shown(d.room)}: {_shown(d.name)} ({_shown(d.reason)}){key}")
        if len(house.dropped) > 10:
            print(f"  ... and {len(house.dropped) - 10} more (see house.json 'dropped')")
    if stand := stand_ins(house.objects):
        names = sorted(Counter(o.name for o in stand).items())
        shown = ", ".join(f"{_shown(n)}" + (f" x{k}" if k > 1 else "") for n, k in names[:8])
        print(f"{len(stand)} object(s) shown with a stand-in mesh (no family draws them yet): "
              f"{shown}{', ...' if len(names) > 8 else ''}")
    for w in house.warnings:
        print(f"Warning: {_shown(w)}")
    times = "  ".join(f"{k} {v:.2f}s" for k, v in timings.items())
    print(f"Time: {total:.2f} s  ({times})")
    print("Files: " + "  ".join(_shown(f) for f in files))


# ---------------------------------------------------------------------- eval
def cmd_eval(args: argparse.Namespace) -> int:
    from anyhome.evaluate import evaluate_house, expectation_for_prompt, load_expectations
    from anyhome.house import load

    house = load(_house_folder(args.path))
    expect = None
    if args.expect:
        if args.id:
            table = load_expectations(args.expect)
            if args.id not in table:
                raise AnyHomeError(f"no entry with id {args.id!r} in {args.expect}")
            expect = table[args.id]
        else:
            expect = expectation_for_prompt(args.expect, house.prompt)
            if expect is None and not args.quiet:
                _err(f"note: no entry in {args.expect} for this house's prompt; coverage skipped")
    report = evaluate_house(house, expect)
    folder = Path(args.path) if Path(args.path).suffix != ".json" else Path(args.path).parent
    if (folder / "house.glb").is_file():
        from anyhome.evaluate.material_words import material_words, summary

        try:
            report.materials = summary(material_words(house, folder / "house.glb"))
        except (OSError, ValueError, KeyError) as e:  # a damaged GLB: the house is still evaluated
            _err(f"note: {folder / 'house.glb'} could not be read ({clean_text(str(e))[:80]}); material words skipped")
    if args.json:
        print(json.dumps(report.to_dict(), indent=1))
    else:
        for line in report.summary_lines():
            print(_shown(line))
    if args.strict and not report.ok:
        return 1
    return 0


def _house_folder(path: str) -> str:
    """``path`` (a house folder or house.json), after putting back a house folder that a
    run killed in the middle of its swap left aside (see anyhome.outdir.prepare)."""
    from anyhome.outdir import prepare

    p = Path(path)
    prepare(p if p.suffix != ".json" else p.parent)
    return path


# -------------------------------------------------------------------- export
def cmd_export(args: argparse.Namespace) -> int:
    from anyhome.house import load
    from anyhome.outdir import check_out
    from anyhome.pipeline import write_exports

    src = Path(args.path)
    out = args.out if args.out is not None else (src if src.is_dir() else src.parent)
    formats = [f.strip().lower() for f in args.format.split(",")]
    real = check_out(out, replace=False)  # before loading: a bad --out is one line, at no cost
    house = load(_house_folder(args.path))
    written = write_exports(house, real, formats)
    print("Files: " + "  ".join(_shown(Path(out) / p.relative_to(real)) for p in written))
    return 0


# -------------------------------------------------------------------- assets
def cmd_assets(args: argparse.Namespace) -> int:
    from anyhome.assets import FAMILIES

    if args.library:
        return _print_library(args.library, args.json)

    if args.json:
        print(json.dumps(list(FAMILIES)))
        return 0
    if args.details:
        from anyhome.assets.catalog import describe

        for d in describe():
            w, dep, h = d["typical_size_m"]
            cats = ", ".join(d.get("categories", [])[:6])
            print(f"{d['name']:<20} {w:.2f} x {dep:.2f} x {h:.2f} m  {d['triangles'][0]}-{d['triangles'][1]} triangles  {cats}")
        return 0
    print(f"{len(FAMILIES)} procedural asset families:")
    for name in FAMILIES:
        print(f"  {name}")
    return 0


def _print_library(folder: str, as_json: bool) -> int:
    """Index an asset library folder and list its models (``anyhome assets --library DIR``)."""
    from anyhome.assets.library import open_library

    lib = open_library(folder)
    rows = [{"path": m.path, "name": m.meta.name, "category": m.meta.category, "tags": list(m.meta.tags),
             "up": m.meta.up, "front": m.meta.front_axis(), "unit": m.unit,
             "size_m": [round(x, 3) for x in m.extents_m]} for m in lib.models]
    if as_json:
        print(json.dumps(rows))
        return 0
    print(f"{len(rows)} models in {_shown(folder)} ({len(lib.loaded)} loaded, the rest from the index):")
    for r in rows:
        w, d, h = r["size_m"]
        print(f"  {_shown(r['path']):<32} {_shown(r['name']):<24} {w:.2f} x {d:.2f} x {h:.2f} m  "
              f"up {r['up']}, front {r['front']}, {r['unit']}")
    return 0


# -------------------------------------------------------------------- render
def cmd_render(args: argparse.Namespace) -> int:
    from anyhome.house import load
    from anyhome.outdir import check_out
    from anyhome.pipeline import write_renders

    _check_render_options(args)
    src = Path(args.path)
    house_dir = src if src.is_dir() else src.parent
    if args.out is not None:
        out = args.out
        real = check_out(out)
    else:  # the house's own folder, re-rendered: its files and the new images
        out = house_dir
        real = check_out(out, what="the house folder")
    house = load(_house_folder(args.path))
    files = write_renders(house_dir, real, lambda folder: _render(house, folder, args))
    print("Files: " + "  ".join(_shown(Path(out) / f.relative_to(real)) for f in files))
    return 0


def _check_render_options(args: argparse.Namespace) -> None:
    """Image sizes in range and a renderer installed, checked before any work."""
    from anyhome.render.api import check_image_sizes
    from anyhome.render.gl import import_moderngl

    check_image_sizes(args.size, args.view_size, names=("--size", "--view-size"))
    import_moderngl()


def _render(house, out: Path, args: argparse.Namespace) -> list[Path]:
    from anyhome.render import render_house

    result = render_house(house, out, size_px=args.size, view_size_px=args.view_size,
                          views=not args.no_views, depth=args.depth, ids=args.depth)
    return [Path(f) for f in result.get("files", [])]


def _render_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--size", type=int, default=1024, help="bird's-eye image size in pixels, 1 to 4096 (default 1024)")
    parser.add_argument("--view-size", type=int, default=512, help="per-room view size in pixels, 1 to 4096 (default 512)")
    parser.add_argument("--no-views", action="store_true", help="only the bird's-eye view")
    parser.add_argument("--depth", action="store_true", help="also write depth and object-id maps")


# ---------------------------------------------------------------------- main
def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="anyhome",
        description="Free-form text to a structured, furnished 3D house, offline.",
    )
    p.add_argument("--version", action="version", version=f"anyhome {__version__}")
    p.add_argument("-v", "--verbose", action="store_true", help="log debug messages")
    sub = p.add_subparsers(dest="command", required=True)

    g = sub.add_parser("generate", help="generate a house from text")
    g.add_argument("text", help="the description, in quotes")
    g.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    g.add_argument("--out", default="out/house", help="output folder (default out/house)")
    g.add_argument("--planner", default="offline", help="planner: offline (default) or llm")
    llm = g.add_argument_group(
        "LLM planner (--planner llm; also from ANYHOME_LLM_* variables and the config file)"
    )
    llm.add_argument("--llm-base-url", help="OpenAI-compatible endpoint (default http://127.0.0.1:8080/v1)")
    llm.add_argument("--llm-model", help="model name (default: the first the server lists)")
    llm.add_argument("--llm-temperature", type=float, help="sampling temperature (default 0.7)")
    llm.add_argument("--llm-top-p", type=float, help="nucleus sampling top-p (default 1.0)")
    llm.add_argument("--llm-max-tokens", type=int, help="most tokens per reply (default 1024)")
    llm.add_argument("--llm-timeout", type=float, help="seconds per request before falling back (default 180)")
    llm.add_argument("--llm-concurrency", type=int, help="per-room requests in flight (default 2)")
    llm.add_argument("--no-cache", action="store_true", help="ask the model again instead of reusing cached replies")
    llm.add_argument("--config", help="TOML config file with an [llm] table and an [assets] dir (default ~/.config/anyhome/config.toml)")
    g.add_argument(
        "--embedder",
        help="text-embedding backend for unknown words: hybrid (default), static, minilm, lexical "
        "(or set ANYHOME_EMBEDDER)",
    )
    g.add_argument(
        "--knowledge", action="append", metavar="DIR",
        help="a folder of knowledge files (objects.yaml, rooms.yaml...) that add to or override the "
        "shipped ones; repeatable, later ones win; after those of ANYHOME_KNOWLEDGE_PATH",
    )
    g.add_argument(
        "--assets", metavar="DIR",
        help="a folder of GLB/GLTF/OBJ/PLY models used for the objects they match by name "
        "(see docs/asset_library.md; or set ANYHOME_ASSETS, or [assets] dir in the config file)",
    )
    g.add_argument("--no-glb", action="store_true", help="skip house.glb")
    g.add_argument("--no-svg", action="store_true", help="skip floorplan.svg")
    g.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    g.add_argument("--json", action="store_true", help="print the summary as JSON")
    g.add_argument("--render", action="store_true", help="also write birdseye.png and views/<room>.png")
    _render_options(g)
    g.set_defaults(func=cmd_generate)

    e = sub.add_parser("eval", help="check a house against the validity rules (and a prompt)")
    e.add_argument("path", help="house folder or house.json")
    e.add_argument("--expect", help="expectations file (JSON lines like shared/eval/prompts.jsonl)")
    e.add_argument("--id", help="use this entry of --expect instead of matching the prompt")
    e.add_argument("--strict", action="store_true", help="exit 1 on any violation")
    e.add_argument("--json", action="store_true", help="print the full report as JSON")
    e.add_argument("-q", "--quiet", action="store_true")
    e.set_defaults(func=cmd_eval)

    x = sub.add_parser("export", help="re-derive house.glb / floorplan.svg from house.json")
    x.add_argument("path", help="house folder or house.json")
    x.add_argument("--format", default="glb,svg", help="comma list: glb,svg (default both)")
    x.add_argument("--out", help="output folder (default: the house's folder)")
    x.set_defaults(func=cmd_export)

    r = sub.add_parser("render", help="render a house headless: birdseye.png and views/<room id>.png")
    r.add_argument("path", help="house folder or house.json")
    r.add_argument("--out", help="output folder (default: the house's folder)")
    _render_options(r)
    r.set_defaults(func=cmd_render)

    a = sub.add_parser("assets", help="list the procedural asset families (or an asset library's models)")
    a.add_argument("--json", action="store_true", help="print a JSON list of family names")
    a.add_argument("--details", action="store_true", help="size, triangles and categories per family")
    a.add_argument("--library", metavar="DIR", help="index an asset library folder and list its models instead")
    a.set_defaults(func=cmd_assets)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    logging.basicConfig(level=logging.DEBUG if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    try:
        return args.func(args)
    except AnyHomeError as e:
        _err(f"error: {e}")
        return 2
    except KeyboardInterrupt:
        _err("interrupted")
        return 130
    except BrokenPipeError:
        # the reader of our output went away (`anyhome eval DIR | head`): stop quietly, as
        # other command-line tools do, with the shell's code for SIGPIPE; whatever was
        # written (a house folder) is already whole
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141


if __name__ == "__main__":
    sys.exit(main())
