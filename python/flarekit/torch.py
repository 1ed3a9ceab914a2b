# SPDX-License-Identifier: Apache-2.0
"""A PyTorch dataset of generated flares, made on the fly in DataLoader workers: item ``i`` is
sample ``i`` of the seed (the same tensors in any worker, in any order). Keys as a Flare7K-style
training step reads them: ``lq`` (the flared image), ``gt`` (the same without the flare, light
sources kept), ``flare`` (the flare alone with its light), ``mask`` (the light sources' clipped
core, one channel) as CHW float tensors in [0, 1], and ``gamma`` (a scalar tensor, the encoding
gamma of lq, gt and flare)."""
import numpy as np
import torch
from torch.utils.data import Dataset

import flarekit.synth as synth

__all__ = ["FlareDataset"]

#: Without a camera model the linear layers are encoded by this gamma, the Flare7K loaders'.
DEFAULT_GAMMA = 2.2


def _encode(linear, gain, gamma):
    return np.clip(linear * gain, 0.0, 1.0) ** (1.0 / gamma)


class FlareDataset(Dataset):
    """``length`` samples of ``seed`` at ``size`` (an int, or (width, height)), drawn as
    ``config`` says (synth.json's keys); ``backgrounds``: a folder of images."""

    def __init__(self, seed, size, config=None, backgrounds=None, length=100_000):
        self.seed = int(seed)
        self.width, self.height = (size, size) if isinstance(size, int) else size
        self.config = dict(config or {})
        if backgrounds is not None:
            self.config["backgrounds"] = str(backgrounds)
        self.length = int(length)

    def __len__(self):
        return self.length

    def __getitem__(self, index):
        if not 0 <= index < self.length:
            raise IndexError(index)
        s = synth.sample(index, self.seed, self.width, self.height, self.config)
        camera = s["label"]["camera"]
        gamma = float(s["label"]["gamma"])
        if camera is None:
            gain = 1.0
            lq = _encode(s["composite"], 1.0, gamma)
            gt = _encode(s["gt"], 1.0, gamma)
        else:  # the camera model already encoded them
            gain = float(camera["gain"])
            lq, gt = s["composite"], s["gt"]
        flare = _encode(s["flare"] + s["light_source"], gain, gamma)
        sources = s["light_source"]
        luminance = sources @ np.array([0.2126, 0.7152, 0.0722], np.float32)
        mask = (luminance >= 1.0).astype(np.float32)[None]

        def chw(a):
            return torch.from_numpy(np.ascontiguousarray(np.transpose(a, (2, 0, 1)),
                                                         dtype=np.float32))

        return {"lq": chw(lq), "gt": chw(gt), "flare": chw(flare),
                "mask": torch.from_numpy(mask), "gamma": torch.tensor(gamma)}
