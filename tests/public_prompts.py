"""Where the public evaluation prompts are: shared/eval beside the clone, else tests/data."""

from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
_SHARED = REPO.parent / "shared" / "eval" / "prompts.jsonl"
PUBLIC_PROMPTS = _SHARED if _SHARED.is_file() else REPO / "tests" / "data" / "public_prompts.jsonl"
