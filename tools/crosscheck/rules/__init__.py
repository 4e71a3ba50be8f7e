"""Rule id -> independent implementation. Each module exports RULES = {id: fn(input) -> output}."""
from . import rng

RULES = {}
for _module in (rng,):
    for _id, _fn in _module.RULES.items():
        assert _id not in RULES, _id
        RULES[_id] = _fn
