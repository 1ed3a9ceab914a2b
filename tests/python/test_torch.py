# SPDX-License-Identifier: Apache-2.0
"""flarekit.torch.FlareDataset feeds a Flare-7K-style training step as it is: two optimisation
steps of a tiny convolutional model on DataLoader batches made in two worker processes."""
import numpy as np
import pytest

torch = pytest.importorskip("torch", reason="python3-torch is installed by scripts/install-deps.sh")

from flarekit.torch import FlareDataset  # noqa: E402


def test_items_are_chw_in_range_and_the_same_in_any_worker():
    data = FlareDataset(seed=3, size=64, length=8)
    item = data[5]
    assert set(item) == {"lq", "gt", "flare", "mask", "gamma"}
    for key in ("lq", "gt", "flare"):
        assert item[key].shape == (3, 64, 64) and item[key].dtype == torch.float32
        assert 0 <= item[key].min() and item[key].max() <= 1
    assert item["mask"].shape == (1, 64, 64)
    assert set(np.unique(item["mask"].numpy())) <= {0.0, 1.0}
    assert item["gamma"].item() == pytest.approx(2.2)
    again = FlareDataset(seed=3, size=64, length=8)[5]
    assert all(torch.equal(item[k], again[k]) for k in item)
    with pytest.raises(IndexError):
        data[8]


def test_two_training_steps_on_worker_batches():
    torch.manual_seed(0)
    data = FlareDataset(seed=1, size=(48, 32), length=8, config={"camera": True})
    loader = torch.utils.data.DataLoader(data, batch_size=2, num_workers=2, shuffle=False)
    model = torch.nn.Sequential(torch.nn.Conv2d(3, 8, 3, padding=1), torch.nn.ReLU(),
                                torch.nn.Conv2d(8, 6, 3, padding=1))
    optimiser = torch.optim.Adam(model.parameters(), lr=1e-3)
    seen = []
    for step, batch in enumerate(loader):
        assert batch["lq"].shape == (2, 3, 32, 48) and batch["gamma"].shape == (2,)
        out = torch.sigmoid(model(batch["lq"]))
        deflared, flare = out[:, :3], out[:, 3:]
        # The Flare7K++ step's shape: the image without its flare, and the flare itself.
        loss = torch.nn.functional.l1_loss(deflared, batch["gt"]) + \
            torch.nn.functional.l1_loss(flare, batch["flare"])
        optimiser.zero_grad()
        loss.backward()
        optimiser.step()
        assert torch.isfinite(loss)
        seen.append(batch["lq"])
        if step == 1:
            break
    # The worker-made batches are the dataset's own items.
    assert torch.equal(seen[1][0], data[2]["lq"])
