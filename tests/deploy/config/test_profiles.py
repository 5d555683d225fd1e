"""The shipped controller profiles: ``porter`` is porter's defaults, ``paper`` the paper's NLP
(its decision variables, none of porter's additions) solved to convergence; found by name or
path, an unknown name refused naming the shipped ones."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.nmpc.settings import MpcSettings
from core.nmpc.transport_problem import build_transport_problem
from deploy.config.files import ConfigError
from deploy.config.profiles import DEFAULT_PROFILES, load_profile, shipped_profiles


def test_the_shipped_profiles_are_porters_defaults_and_the_papers_nlp() -> None:
    assert shipped_profiles() == ["paper", "porter"] and set(DEFAULT_PROFILES) == {"paper",
                                                                                    "porter"}
    assert load_profile("porter") == ("porter", MpcSettings())
    label, paper = load_profile("paper")
    assert label == "paper"
    defaults = MpcSettings()
    assert paper.solver.name == "ipopt-reference" and paper.coupling.yaw_torque == "penalize"
    assert not paper.safety.first_order_condition and not paper.safety.soft_barriers
    assert paper.safety.obstacle_slots == paper.safety.max_obstacles
    assert paper.capability.max_planar_speed_m_s is None
    assert paper.capability.max_height_deviation_m is None
    # what the paper states and porter's defaults share stays the default
    assert paper.admm == defaults.admm and paper.cost == defaults.cost
    assert paper.horizon_steps == 8 and paper.safety.alpha1 == 0.4


def test_the_paper_profile_has_the_papers_decision_variables() -> None:
    """Table I: 408 per local NLP and 612 centralized for two agents (N (2 n_x + n_u + n_A
    n_lambda) + 2 n_x and (n_A + 1)(N + 1) n_x + n_A N (n_u + n_lambda)); porter's add one
    slack per stage."""
    _, paper = load_profile("paper")
    assert build_transport_problem(paper, 2, local=True).nlp.variable_count == 408
    assert build_transport_problem(paper, 2, local=False).nlp.variable_count == 612
    assert build_transport_problem(MpcSettings(), 2, local=True).nlp.variable_count == 416


def test_a_profile_is_found_by_path_and_an_unknown_name_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "mine.yaml"
    path.write_text("admm: {iterations: 3}\n")
    label, settings = load_profile(str(path))
    assert label == "mine" and settings.admm.iterations == 3
    with pytest.raises(ConfigError, match="unknown profile 'nowhere'; shipped profiles: "
                                          "paper, porter"):
        load_profile("nowhere")


def test_porter_sim_takes_a_profile_by_name_and_refuses_an_unknown_one(
        capsys: pytest.CaptureFixture[str]) -> None:
    import argparse

    from deploy.cli.porter import main, mpc_settings

    assert mpc_settings(argparse.Namespace(config="paper")) == load_profile("paper")[1]
    assert mpc_settings(argparse.Namespace(config=None)) == MpcSettings()
    assert main(["sim", "--config", "nowhere", "--no-record", "--duration", "0.1"]) == 2
    assert "unknown profile 'nowhere'" in capsys.readouterr().err
