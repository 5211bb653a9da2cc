"""Training-split augmentation of occupancy submaps, as in the thesis: rotation and jitter.

Rotating a robot-centred submap is the same scene seen with another heading, and a small shift is
a small position error; both keep the zone label. Uncovered pixels become 'unknown' (grey 128),
exactly what the submap builder writes where the lidar saw nothing.
"""
import math
from dataclasses import dataclass

import torch
import torch.nn.functional as F

UNKNOWN_GREY = 128

# How far training images are turned, by the dataset's submap orientation. Heading-up submaps
# come at every heading. Wall-aligned ones are turned by the scan's own wall estimate, which is
# off by under 2 deg in 99 % of office_two_zone's samples (samples.csv: image_heading_rad against
# phi_rad); 3 deg covers that.
MAX_ROTATION_DEG = {"heading_up": 180.0, "wall_axes": 3.0}


def max_rotation_deg(card: dict) -> float:
    """The training rotation for a dataset card; cards from before orientations were heading up."""
    orientation = card["submap"].get("orientation", "heading_up")
    if orientation not in MAX_ROTATION_DEG:
        raise ValueError(f"dataset card: unknown submap orientation '{orientation}' "
                         f"(known: {', '.join(MAX_ROTATION_DEG)})")
    return MAX_ROTATION_DEG[orientation]


@dataclass
class AugmentParams:
    max_rotation_deg: float = 180.0  # headings are sampled uniformly, so any rotation is plausible
    max_shift_px: float = 4.0  # about half a metre at 0.15 m per pixel


def augment_batch(images_uint8: torch.Tensor, params: AugmentParams, generator: torch.Generator) -> torch.Tensor:
    """Random rotation about the image centre and a random shift, nearest-neighbour, per image."""
    n = images_uint8.shape[0]
    angles = (torch.rand(n, generator=generator) * 2 - 1) * math.radians(params.max_rotation_deg)
    shifts = (torch.rand(n, 2, generator=generator) * 2 - 1) * params.max_shift_px
    h, w = images_uint8.shape[-2:]
    cos, sin = torch.cos(angles), torch.sin(angles)
    theta = torch.zeros(n, 2, 3)
    theta[:, 0, 0], theta[:, 0, 1] = cos, -sin
    theta[:, 1, 0], theta[:, 1, 1] = sin, cos
    theta[:, 0, 2] = shifts[:, 0] * 2.0 / w
    theta[:, 1, 2] = shifts[:, 1] * 2.0 / h
    grid = F.affine_grid(theta, list(images_uint8.shape), align_corners=False)
    # Sample (value - unknown) so that zero padding outside the image comes back as 'unknown'.
    centred = images_uint8.float() - UNKNOWN_GREY
    out = F.grid_sample(centred, grid, mode="nearest", padding_mode="zeros", align_corners=False)
    return (out + UNKNOWN_GREY).round().clamp(0, 255).to(torch.uint8)
