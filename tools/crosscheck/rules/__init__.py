"""Rule id -> independent implementation. Each module exports RULES = {id: fn(input) -> output}."""
from . import rng
from . import search
from . import grid
from . import metrics
from . import mecanum
from . import shi2022
from . import inflation
from . import han
from . import han_sim
from . import ga_planners
from . import aco_planners
from . import cin2021
from . import cin2021_srrt
from . import cin2021_ml
from . import stats
from . import sensors2023_dwa
from . import curves
from . import sensors2023

RULES = {}
for _module in (rng, search, grid, metrics, mecanum, shi2022, han, han_sim, inflation, ga_planners, aco_planners, cin2021,
                cin2021_srrt, cin2021_ml, stats, sensors2023_dwa, curves, sensors2023):
    for _id, _fn in _module.RULES.items():
        assert _id not in RULES, _id
        RULES[_id] = _fn
