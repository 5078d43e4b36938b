"""What a designed machine's chain gains with a gas spring at every interface, from its saved design:
``python scripts/gas-spring-chain.py RUN/12lb/machine.json`` (the ``machine.json`` that ``shockfem
design-machine`` or ``shockfem study premise`` writes) prints the premise report's gas-spring tables
(``machine.gas_spring_chain``, ``study.system_premise.gas_spring_section``) for it, without designing again.
The chain needs the spec and the fixture's striker and housing only."""
import json
import sys
import tempfile
import types

from shockfem.machine.spec import read_spec
from shockfem.study import system_premise
from shockfem.study.report import Report

FIXTURE_FIELDS = ("striker_mass", "striker_speed", "housing_outer_radius", "housing_length", "bore_radius",
                  "bore_depth")


def main(path: str) -> None:
    with open(path) as fh:
        saved = json.load(fh)
    spec = read_spec({"article": f"{saved['spec']['article_mass']} kg"})
    fixture = types.SimpleNamespace(**{k: saved["fixture"][k] for k in FIXTURE_FIELDS})
    out = tempfile.mkdtemp()
    rep = Report(out, "gas springs on the saved machine's chain")
    system_premise.gas_spring_section(rep, types.SimpleNamespace(spec=spec, fixture=fixture))
    with open(rep.path("report.md")) as fh:
        print(fh.read())


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python scripts/gas-spring-chain.py MACHINE_JSON")
    main(sys.argv[1])
