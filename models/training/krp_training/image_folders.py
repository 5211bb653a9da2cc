"""Reads krp-dataset's classifier folders (classifier/<split>/<zone>/<id>.png) into memory."""
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import torch
from PIL import Image

SPLITS = ("train", "val", "test", "changed")


@dataclass
class ImageSet:
    images: torch.Tensor  # N x 1 x H x W, uint8 grey levels as krp-dataset wrote them
    labels: torch.Tensor  # N, int64 zone index in the dataset card's zone order
    ids: list

    def __len__(self):
        return len(self.labels)

    def subset(self, mask) -> "ImageSet":
        idx = torch.nonzero(torch.as_tensor(mask), as_tuple=False).flatten()
        return ImageSet(self.images[idx], self.labels[idx], [self.ids[i] for i in idx.tolist()])


def read_split(dataset_dir: Path, split: str, zones: list) -> ImageSet:
    root = Path(dataset_dir) / "classifier" / split
    if not root.is_dir():
        raise FileNotFoundError(f"{root}: no such split folder (is {dataset_dir} a krp-dataset output?)")
    unknown = sorted(p.name for p in root.iterdir() if p.is_dir() and p.name not in zones)
    if unknown:
        raise ValueError(f"{root}: folders {unknown} are not zones of the dataset card ({zones})")
    images, labels, ids = [], [], []
    for index, zone in enumerate(zones):
        for png in sorted((root / zone).glob("*.png")) if (root / zone).is_dir() else []:
            grey = np.asarray(Image.open(png).convert("L"), dtype=np.uint8)
            images.append(grey)
            labels.append(index)
            ids.append(png.stem)
    if not images:
        return ImageSet(torch.zeros((0, 1, 1, 1), dtype=torch.uint8), torch.zeros(0, dtype=torch.int64), [])
    stacked = torch.from_numpy(np.stack(images)).unsqueeze(1)
    return ImageSet(stacked, torch.tensor(labels, dtype=torch.int64), ids)
