"""soilcut.gym: the environment passes gymnasium's checker, a random policy's
episode ends with finite rewards, a seed gives one episode bit for bit, and
the reward is the soil moved per unit of work of the step's records."""

from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

gymnasium = pytest.importorskip("gymnasium")

import soilcut  # noqa: E402
import soilcut.gym  # noqa: E402  (registers soilcut/Cutting-v0)
from soilcut.gym import CuttingEnv  # noqa: E402


def short(**kwargs) -> CuttingEnv:
    """The default tine over 1 d in steps of d/5 (10 increments each)."""
    case = soilcut.gym.default_case().set("run.increment", 3.0)
    return CuttingEnv(case, travel=1.0, step_travel=0.2, **kwargs)


def rollout(env, seed: int):
    """A random policy's episode: its observations, rewards and infos."""
    obs, info = env.reset(seed=seed)
    env.action_space.seed(seed)
    observations, rewards, infos = [obs], [], [info]
    for _ in range(100):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        observations.append(obs)
        rewards.append(reward)
        infos.append(info)
        if terminated or truncated:
            return observations, rewards, infos, terminated
    raise AssertionError("the episode did not end")


def test_check_env_passes():
    from gymnasium.utils.env_checker import check_env

    env = gymnasium.make(soilcut.gym.ENV_ID, case=short().case, travel=0.5, step_travel=0.25)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the checker's warnings too
        check_env(env.unwrapped)


def test_make_builds_the_default_environment():
    env = gymnasium.make("soilcut/Cutting-v0")
    assert isinstance(env.unwrapped, CuttingEnv)
    assert env.observation_space.shape == (11,)
    assert env.action_space.shape == (1,)
    assert env.unwrapped.travel == 450.0 and env.unwrapped.step_travel == 15.0


def test_a_random_policy_ends_with_finite_rewards():
    env = short()
    observations, rewards, infos, terminated = rollout(env, seed=3)
    assert terminated and len(rewards) == 5
    assert np.all(np.isfinite(rewards)) and "error" not in infos[-1]
    assert all(env.observation_space.contains(o) for o in observations)
    assert infos[-1]["u"] == pytest.approx(150.0)
    with pytest.raises(RuntimeError, match="ended"):
        env.step(env.action_space.sample())
    lo, hi = env.depth_range
    depths = [i["depth"] for i in infos]
    assert all(lo <= x <= hi for x in depths) and len(set(depths)) > 2


def test_the_default_environment_runs_a_random_episode():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # gymnasium's passive checker warns
        env = gymnasium.make("soilcut/Cutting-v0")
        observations, rewards, infos, terminated = rollout(env, seed=11)
    assert terminated and len(rewards) == 30 and np.all(np.isfinite(rewards))
    assert infos[-1]["u"] == 450.0 and "error" not in infos[-1]
    assert all(env.observation_space.contains(o) for o in observations)


def test_the_same_seed_gives_the_same_episode_bit_for_bit():
    env = short()
    a = rollout(env, seed=7)
    b = rollout(gymnasium.make(soilcut.gym.ENV_ID, case=env.case, travel=1.0, step_travel=0.2), 7)
    c = rollout(short(), seed=8)
    for x, y in zip(a[0], b[0]):
        assert x.tobytes() == y.tobytes()
    assert a[1] == b[1] and a[2] == b[2]
    assert a[0][0].tobytes() != c[0][0].tobytes()


def test_the_seed_draws_the_start_depth_and_the_perturbation():
    env = short()
    _, info = env.reset(seed=1)
    first = (info["depth"], env.sim.case["blade.wall_friction"])
    _, info = env.reset(seed=2)
    second = (info["depth"], env.sim.case["blade.wall_friction"])
    assert first != second
    assert 75.0 <= first[0] <= 150.0
    assert abs(first[1] - 20.0) <= 0.03 and first[1] != 20.0
    _, info = env.reset(seed=1, options={"depth": 0.8, "perturb": False})
    assert info["depth"] == 120.0 and env.sim.case["blade.wall_friction"] == 20.0


def test_the_reward_is_soil_moved_per_unit_of_work():
    env = short(force_limit=1e6)
    env.reset(seed=0, options={"depth": 0.6, "perturb": False})
    twin = soilcut.Simulation(env.sim.case)
    _, reward, _, _, info = env.step(np.array([0.5], dtype=np.float32))
    records = twin.advance_to(30.0, depth=90.0 + 0.5 * 30.0)
    v0, gamma0, width = 3.0, 1.57e-5, 50.0
    moved = gamma0 * width * sum(r.depth for r in records) * v0
    work = sum(r.force_h for r in records) * v0
    assert info["soil_moved"] == moved and info["work"] == work
    assert reward == pytest.approx(150.0 * moved / work, rel=1e-12)
    assert info["depth"] == 105.0 and not info["clipped"]


def test_the_force_limit_penalises_and_the_depth_is_clipped():
    free, limited = short(force_limit=1e6), short(force_limit=1.0, overload_penalty=2.0)
    rewards = []
    for env in (free, limited):
        env.reset(seed=0, options={"depth": 1.0})
        _, reward, _, _, info = env.step(np.array([0.5], dtype=np.float32))
        rewards.append(reward)
        assert info["depth"] == 150.0 and info["clipped"]  # already at depth_range's end
    peak = info["max_force_h"] / limited.f0
    assert peak > 1.0
    assert rewards[1] == pytest.approx(rewards[0] - 2.0 * (peak - 1.0), rel=1e-12)
    _, _, _, _, info = free.step(np.array([-7.0]))  # outside the box: clipped to -0.5
    assert info["clipped"] and info["depth"] == pytest.approx(150.0 - 0.5 * 30.0)


class Failing:
    """A simulation whose advance_to makes half its increments and then
    raises soilcut.StepError with their records, as one does when an
    increment has no admissible mechanism (no case of the tine in range
    reaches that, so the failure is stood in for)."""

    def __init__(self, sim):
        self.sim = sim

    def advance_to(self, x, depth=None):
        made = self.sim.advance_to(0.5 * (self.sim.blade_position + x), depth=depth)
        raise soilcut.StepError("increment 16: no admissible mechanism", steps=made)

    def __getattr__(self, name):
        return getattr(self.sim, name)


def test_no_admissible_mechanism_ends_the_episode_with_the_penalty():
    env = short(failure_penalty=3.0)
    env.reset(seed=0)
    _, _, _, _, first = env.step(np.array([0.0]))
    env.sim = Failing(env.sim)
    obs, reward, terminated, truncated, info = env.step(np.array([0.0]))
    assert terminated and not truncated and reward == -3.0
    assert "no admissible mechanism" in info["error"]
    assert env.observation_space.contains(obs)
    # The five increments made before the failure count, as a step's do.
    assert info["u"] == pytest.approx(first["u"] * 1.5, rel=1e-12)
    assert info["soil_moved"] == pytest.approx(0.5 * first["soil_moved"], rel=1e-9)
    assert 0.0 < info["work"] and 0.0 < info["max_force_h"]
    with pytest.raises(RuntimeError, match="ended"):
        env.step(np.array([0.0]))


def test_bad_arguments_raise():
    with pytest.raises(ValueError, match="rake"):
        CuttingEnv(short().case.set("blade.rake", 60.0))
    with pytest.raises(ValueError, match="depth_range"):
        short(depth_range=(0.5, 1.5))
    with pytest.raises(soilcut.CaseError, match="shallowest"):
        short(depth_range=(0.01, 1.0))  # 1.5 mm, less than run.increment
    env = short()
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.array([0.0]))
    env.reset(seed=0)
    with pytest.raises(ValueError, match="NaN"):
        env.step(np.array([np.nan]))
    with pytest.raises(ValueError, match=r"^action: expected one depth rate .* shape \(2,\)$"):
        env.step(np.array([0.1, 0.2]))


def test_a_case_files_path_is_taken_where_a_case_is(tmp_path):
    path = tmp_path / "tine.toml"
    path.write_text(short().case.to_toml(), encoding="utf-8")
    for given in (path, str(path)):
        env = CuttingEnv(given, travel=1.0, step_travel=0.2)
        assert env.case == short().case


def test_import_soilcut_gym_without_gymnasium_names_the_pip_command():
    code = (
        "import sys; sys.modules['gymnasium'] = None\n"
        "import soilcut\n"
        "try:\n    import soilcut.gym\n"
        "except ImportError as e:\n    print(e)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "pip install gymnasium" in done.stdout
