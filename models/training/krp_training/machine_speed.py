"""How fast this machine trains, measured in a second before the long stages start.

krp-train-map's time estimate multiplies the image count by per-image costs measured on one
machine. The same 2-core development machines have trained the compact classifier at 0.0069 to
0.0107 s per image-epoch in some sessions and at 0.0013 s in another, so fixed costs can be 7x
off. A few SGD steps of the compact classifier on this machine, against the same steps on the
machine that measured the costs, scale them. Both training stages moved by the same factor
between those machines (compact 0.0069-0.0107 to 0.0013 s, YOLOv8n-pose 0.072-0.080 to 0.015 s),
so the one probe scales the keypoint stage's cost too.
"""
import statistics
import time

import torch
from torch import nn

from . import classifier_models
from .train_classifier import ClassifierParams

PROBE_BATCH = ClassifierParams.batch_size  # the batch the classifier trains with
PROBE_STEPS = 5  # timed steps, after one untimed warm-up step; the median is kept
PROBE_CLASSES = 4


def probe_step_seconds(input_px: int = 160, steps: int = PROBE_STEPS) -> float:
    """Median wall seconds of one training step (forward, backward, SGD update) of the compact classifier
    on random submap-sized images, on the CPU with torch's current thread settings (a GPU run needs no
    estimate: its progress bars come fast enough)."""
    if steps < 1:
        raise ValueError("probe_step_seconds: steps must be >= 1")
    # The compact classifier takes only multiples of its stride; a submap of another size (which
    # another architecture may train on) is probed at the nearest one: the probe times the machine.
    stride = classifier_models.CompactNet.STRIDE
    input_px = max(stride, round(input_px / stride) * stride)
    gen = torch.Generator().manual_seed(0)
    model = classifier_models.build("compact", PROBE_CLASSES, input_px=input_px)
    model.train()
    opt = torch.optim.SGD(model.parameters(), lr=0.01, momentum=0.9)
    loss_fn = nn.CrossEntropyLoss()
    x = torch.rand((PROBE_BATCH, 1, input_px, input_px), generator=gen)
    y = torch.randint(0, PROBE_CLASSES, (PROBE_BATCH,), generator=gen)
    times = []
    for step in range(steps + 1):
        t0 = time.perf_counter()
        opt.zero_grad()
        loss_fn(model(x), y).backward()
        opt.step()
        if step > 0:  # the first step allocates and picks kernels
            times.append(time.perf_counter() - t0)
    return statistics.median(times)
