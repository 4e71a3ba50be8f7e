"""Rule id -> independent implementation. Each module exports RULES = {id: fn(input) -> output}."""
from . import rng
from . import search
from . import grid
from . import metrics
from . import mecanum
from . import shi2022
from . import inflation
from . import han

RULES = {}
for _module in (rng, search, grid, metrics, mecanum, shi2022, han, inflation):
    for _id, _fn in _module.RULES.items():
        assert _id not in RULES, _id
        RULES[_id] = _fn
