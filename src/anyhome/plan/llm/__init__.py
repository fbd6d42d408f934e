"""The LLM planner: any OpenAI-compatible chat model plans the house (see planner.py)."""

from anyhome.plan.llm.config import LLMConfig, load_config
from anyhome.plan.llm.planner import LLMPlanner

__all__ = ["LLMConfig", "LLMPlanner", "load_config"]
