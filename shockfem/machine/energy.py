"""Every joule of a shot: from the gas stored in the tank to what each stop absorbs.

Each row comes from the model that owns it, so that the table closes only if the models agree:

* the gun (``launcher.gun.fire`` on the designed gun, its own energy accounts): the gas's stored internal
  energy p0 V0 / (gamma - 1) (counted from vacuum), what it still holds when the first mass leaves the
  muzzle, and so the **gas work** (what it gave up), spent on the gas column's own motion (Lagrange), the
  air ahead, friction and the first mass's kinetic energy; beside them the isentropic work
  p0 V0 (1 - (V0 / V1)^(gamma - 1)) / (gamma - 1) of the stored gas expanding into the barrel (V1 = V0 +
  the bore's volume), the most any valve and barrel of this gun could draw from it;
* the amplifier's chain as designed (``machine.amplifier.chain_run``: the rigid chain at each interface's
  restitution measured by its pad's finite-element run, or its material's estimate where the run was not
  made, every collision followed): each interface's loss (what its pad and the bodies' waves in its run
  did not return, over every collision at that interface) and each mass's kinetic energy after its last
  collision, which its stop takes;
* the fixture (its column run, ``machine.fixture``): the energy the oil takes from striker and payload
  (integrated from its floor pressure on the housing and its force on the payload, not the bodies'
  speeds, ``fixture.oil_work``), the payload's kinetic energy (which the catcher takes) and the
  striker's after the pulse (which its stop takes).

The parts (the gun's losses, the interfaces', every stop's, the oil's and the payload's) must sum to
the gas work: what they miss is how far the gun's muzzle speed, the chain's launch and striker speeds and
the fixture's striker speed disagree (``verify machine_energy`` holds it within 0.5%).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

from ..amplifier import rigid
from ..launcher.gun import fire

# the closure ``verify machine_energy`` asks of the parts against the gas work
CLOSURE_TOL = 5e-3


@dataclass
class EnergyRow:
    name: str
    energy: float              # [J]
    group: str                 # "gas", "gun", "interface", "stop", "fixture", "payload", "through"
    part: bool                 # one of the parts that sum to the gas work
    note: str = ""


@dataclass
class EnergyTable:
    rows: list[EnergyRow]
    stored: float              # the tank's gas, p0 V0 / (gamma - 1) [J]
    isentropic: float          # its isentropic work expanding into the barrel [J]
    gas_work: float            # what the gas gave up over the shot [J]
    parts: float               # the parts' sum [J]
    closure: float             # (parts - gas work) / gas work [-]
    payload: float             # the payload's kinetic energy after the pulse [J]
    chain_source: str
    notes: list[str] = field(default_factory=list)
    # the chain's launch energy (at the design's launch speed) less the first mass's at the gun's muzzle [J]:
    # zero when the gun reaches the launch speed; a gun that falls short leaves the table open by this much
    shortfall: float = 0.0

    @property
    def models_closure(self) -> float:
        """(parts - gas work - shortfall) / gas work: how far the models disagree on what they hand each
        other, the gun's shortfall taken out [-]."""
        return (self.parts - self.gas_work - self.shortfall) / self.gas_work

    def as_dict(self) -> dict:
        return {**asdict(self), "models_closure": self.models_closure}


def isentropic_work(p0: float, V0: float, V1: float, gamma: float) -> float:
    """An ideal gas's work expanding isentropically from (p0, V0) to V1 [J]: p0 V0 (1 - (V0 / V1)^(gamma - 1))
    / (gamma - 1)."""
    return p0 * V0 * (1 - (V0 / V1) ** (gamma - 1)) / (gamma - 1)


@dataclass
class ChainRecord:
    """The chain's energies: each body's speed after its last stage, each interface's loss [J]."""
    final_speeds: dict          # body -> [m/s]
    losses: dict                # "m1_m2" -> [J]
    striker_speed: float        # the last body's [m/s]
    launch_energy: float        # the chain's kinetic energy at the start [J]
    source: str


def chain_record(masses: list[float], names: list[str], launch: float, architecture: str,
                 result: rigid.ChainResult, source: str) -> ChainRecord:
    """The chain's record from its rigid run ``result`` (``rigid.run_chain``: every collision, each at its
    interface's restitution); ``source`` says which restitutions it ran on."""
    m = dict(zip(names, masses))
    launched = masses[:1] if architecture == "launched-chain" else masses
    start = 0.5 * sum(launched) * launch * launch
    stages = [{"striker": names[c.left] if c.left >= 0 else "anvil", "struck": names[c.right],
               "striker_before": c.before[0], "striker_after": c.after[0],
               "struck_before": c.before[1], "struck_after": c.after[1]} for c in result.collisions]
    speeds = {n: (launch if (architecture != "launched-chain" or k == 0) else 0.0) for k, n in enumerate(names)}
    losses: dict[str, float] = {}
    for st in stages:
        a, b = st["striker"], st["struck"]
        key = f"{a}_{b}"
        loss = 0.0
        for body, before, after in ((a, st["striker_before"], st["striker_after"]),
                                    (b, st["struck_before"], st["struck_after"])):
            if body in m:
                loss += 0.5 * m[body] * (before * before - after * after)
                speeds[body] = after
        losses[key] = losses.get(key, 0.0) + loss
    return ChainRecord({k: abs(v) for k, v in speeds.items()}, losses, abs(speeds[names[-1]]), start, source)


def energy_table(launcher, amp, fixture, stops, record: ChainRecord) -> EnergyTable:
    """The shot's energy table: the designed gun fired again for its accounts, the chain's ``record``,
    the fixture's column run and the layout's ``stops``."""
    g = launcher.design.gun
    shot = fire(g)
    E = shot.energies
    gas = g.gas_model()
    stored = g.reservoir_pressure * g.reservoir_volume / (gas.gamma - 1)
    V1 = g.reservoir_volume + g.area * g.length
    gas_work = E["initial"] - E["gas_left"]
    rows = [EnergyRow("gas stored in the tank (p0 V0 / (gamma - 1), from vacuum)", stored, "gas", False),
            EnergyRow("its isentropic work expanding into the barrel (the most the gun could draw)",
                      isentropic_work(g.reservoir_pressure, g.reservoir_volume, V1, gas.gamma), "gas", False),
            EnergyRow("gas left in tank and barrel at the muzzle", E["gas_left"], "gas", False),
            EnergyRow("gas work (what the gas gave up: the parts below sum to it)", gas_work, "gas", False),
            EnergyRow("the gas column's own motion (Lagrange)", E["gas_kinetic"], "gun", True),
            EnergyRow("the air ahead of the first mass", E["air_ahead"], "gun", True),
            EnergyRow("bore friction", E["friction"], "gun", True),
            EnergyRow(f"launched mass at the muzzle ({launcher.projectile_mass:,.0f} kg at "
                      f"{shot.muzzle_velocity:.2f} m/s)", E["projectile"], "through", False)]
    for key, loss in record.losses.items():
        rows.append(EnergyRow(f"interface {key} (pads, waves, damping)", loss, "interface", True))
    by_body = {s.body: s for s in stops}
    striker = amp.bodies[-1]["name"] if amp.bodies else "striker"
    for name, v in record.final_speeds.items():
        if name == striker:
            continue
        s = by_body.get(name)
        mass = amp.masses[[b["name"] for b in amp.bodies].index(name)]
        rows.append(EnergyRow(f"{name} after its stages -> its stop" + (f" ({s.kind})" if s else ""),
                              0.5 * mass * v * v, "stop", True,
                              f"the layout's stop takes {s.energy:.6g} J" if s else ""))
    M, V = fixture.striker_mass, fixture.striker_speed
    rows.append(EnergyRow(f"striker at impact (the chain: {record.striker_speed:.2f} m/s)",
                          0.5 * M * record.striker_speed ** 2, "through", False))
    rows.append(EnergyRow(f"striker at impact (the fixture: {V:.2f} m/s)", 0.5 * M * V * V, "through", False))
    rows.append(EnergyRow("the fixture's oil (its pressures and jet on the two bodies)", fixture.oil_work, "fixture",
                          True))
    payload = 0.5 * fixture.payload_mass * fixture.after_speed_payload ** 2
    st, ct = by_body.get("striker"), by_body.get("payload")
    rows.append(EnergyRow("striker after the pulse -> its stop" + (f" ({st.kind})" if st else ""),
                          0.5 * M * fixture.after_speed_striker ** 2, "stop", True))
    rows.append(EnergyRow("payload (article and piston) after the pulse -> the catcher" + (f" ({ct.kind})" if ct else ""),
                          payload, "payload", True))
    parts = sum(r.energy for r in rows if r.part)
    notes = [f"chain: {record.source}",
             f"the gun fires at {shot.muzzle_velocity:.4f} m/s, the chain was launched at "
             f"{math.sqrt(2 * record.launch_energy / sum(amp.masses[:1] if amp.architecture == 'launched-chain' else amp.masses)):.4f} m/s",
             f"the chain gives the striker {record.striker_speed:.3f} m/s, the fixture takes it at {V:.3f} m/s"]
    launched = math.sqrt(2 * record.launch_energy / sum(amp.masses[:1] if amp.architecture == "launched-chain"
                                                         else amp.masses))
    if shot.muzzle_velocity < launched * (1 - 1e-3):
        # the rigid chain's speeds scale with its launch: the shot this machine fires, beside the one it needs
        notes.append(f"the shot this machine fires: the gun launches at {shot.muzzle_velocity:.4g} m/s, so the chain "
                     f"brings the striker to {record.striker_speed * shot.muzzle_velocity / launched:.4g} m/s "
                     f"({shot.muzzle_velocity / launched:.2%} of the {V:.4g} m/s the pulse needs); the table is the "
                     "shot the design needs, the gun's shortfall beside it")
    return EnergyTable(rows, stored, rows[1].energy, gas_work, parts, parts / gas_work - 1, payload, record.source,
                       notes, record.launch_energy - E["projectile"])


def energy_figure(table: EnergyTable, path: str, title: str):
    """Two bars: the stored gas (what is left and the gas work) and the gas work split into its parts [MJ]."""
    from ..output.figures import pyplot, save
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(9, 4.8))
    colours = {"gun": "#999999", "interface": "#d95f02", "stop": "#7570b3", "fixture": "#1b9e77", "payload": "#e7298a"}
    left = table.stored - table.gas_work
    ax.barh(1, left / 1e6, color="#cccccc", label="gas left in tank and barrel")
    ax.barh(1, table.gas_work / 1e6, left=left / 1e6, color="#66a61e", label="gas work")
    x = 0.0
    seen = set()
    for r in (r for r in table.rows if r.part):
        label = r.group if r.group not in seen else None
        seen.add(r.group)
        ax.barh(0, r.energy / 1e6, left=x / 1e6, color=colours[r.group], edgecolor="white", linewidth=0.5,
                label={"gun": "gun: gas motion, air, friction", "interface": "interfaces", "stop": "stops",
                       "fixture": "fixture's oil", "payload": "payload"}[r.group] if label else None)
        x += r.energy
    ax.set_yticks([0, 1])
    ax.set_yticklabels(["gas work, split", "gas stored"])
    ax.set_xlabel("energy [MJ]")
    ax.set_title(title + f"\npayload {table.payload / 1e6:.3g} MJ = {table.payload / table.stored:.2%} of the stored gas; "
                 f"closure {table.closure:+.2%}", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(axis="x", alpha=0.3)
    save(fig, path)
    return path
