"""Test configuration: puts tests/ on sys.path so tests can import public_prompts."""
