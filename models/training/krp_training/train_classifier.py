"""Trains a zone classifier on krp-dataset's occupancy images (SGD with momentum, as the thesis)."""
import copy
import time
from dataclasses import dataclass, field, asdict

import torch
from torch import nn
from tqdm import tqdm

from . import classifier_models
from .augment import AugmentParams, augment_batch
from .image_folders import ImageSet


@dataclass
class ClassifierParams:
    architecture: str = "compact"
    epochs: int = 30
    batch_size: int = 32
    learning_rate: float = 0.02
    momentum: float = 0.9
    weight_decay: float = 1e-3  # the thesis's value
    dropout: float = 0.3
    augment: AugmentParams = field(default_factory=AugmentParams)
    seed: int = 1
    device: str = "cpu"


@dataclass
class ClassifierResult:
    model: nn.Module
    history: list  # per epoch: {"epoch", "train_loss", "train_acc", "val_loss", "val_acc", "seconds"}
    best_epoch: int
    seconds: float
    params: dict


def _batches(n: int, batch_size: int, generator=None):
    order = torch.randperm(n, generator=generator) if generator is not None else torch.arange(n)
    for start in range(0, n, batch_size):
        yield order[start:start + batch_size]


@torch.no_grad()
def predict(model: nn.Module, images_uint8: torch.Tensor, device: str = "cpu", batch_size: int = 64) -> torch.Tensor:
    """Class probabilities, N x classes."""
    model.eval()
    out = []
    for idx in _batches(len(images_uint8), batch_size):
        x = classifier_models.normalize(images_uint8[idx]).to(device)
        out.append(torch.softmax(model(x), dim=1).cpu())
    return torch.cat(out) if out else torch.zeros((0, 0))


def _evaluate(model, data: ImageSet, device: str):
    if len(data) == 0:
        return float("nan"), float("nan")
    probs = predict(model, data.images, device)
    loss = nn.functional.nll_loss(torch.log(probs.clamp_min(1e-12)), data.labels).item()
    return loss, (probs.argmax(1) == data.labels).float().mean().item()


def train(train_set: ImageSet, val_set: ImageSet, num_classes: int, params: ClassifierParams,
          progress_label: str = "") -> ClassifierResult:
    """Trains for params.epochs and keeps the weights of the epoch with the best validation accuracy."""
    if len(train_set) == 0:
        raise ValueError("the training split is empty")
    torch.manual_seed(params.seed)
    gen = torch.Generator().manual_seed(params.seed)
    model = classifier_models.build(params.architecture, num_classes, params.dropout,
                                    input_px=train_set.images.shape[-1]).to(params.device)
    opt = torch.optim.SGD(model.parameters(), lr=params.learning_rate, momentum=params.momentum,
                          weight_decay=params.weight_decay, nesterov=True)
    steps = params.epochs * ((len(train_set) + params.batch_size - 1) // params.batch_size)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, max_lr=params.learning_rate, total_steps=max(steps, 1))
    loss_fn = nn.CrossEntropyLoss()
    history, best = [], (-1.0, 0, None)
    start = time.perf_counter()
    bar = tqdm(range(params.epochs), desc=f"classifier {progress_label or params.architecture}", unit="epoch")
    for epoch in bar:
        t0 = time.perf_counter()
        model.train()
        total_loss, correct = 0.0, 0
        for idx in _batches(len(train_set), params.batch_size, gen):
            x = augment_batch(train_set.images[idx], params.augment, gen)
            x = classifier_models.normalize(x).to(params.device)
            y = train_set.labels[idx].to(params.device)
            if len(idx) < 2:  # BatchNorm cannot train on a single image
                continue
            opt.zero_grad()
            logits = model(x)
            loss = loss_fn(logits, y)
            loss.backward()
            opt.step()
            sched.step()
            total_loss += loss.item() * len(idx)
            correct += (logits.argmax(1) == y).sum().item()
        val_loss, val_acc = _evaluate(model, val_set, params.device)
        row = {"epoch": epoch + 1, "train_loss": total_loss / len(train_set), "train_acc": correct / len(train_set),
               "val_loss": val_loss, "val_acc": val_acc, "seconds": time.perf_counter() - t0}
        history.append(row)
        bar.set_postfix(loss=f"{row['train_loss']:.3f}", val_acc=f"{val_acc:.3f}")
        if val_acc > best[0] or best[2] is None:
            best = (val_acc, epoch + 1, copy.deepcopy(model.state_dict()))
    model.load_state_dict(best[2])
    model.eval()
    p = asdict(params)
    return ClassifierResult(model, history, best[1], time.perf_counter() - start, p)


def evaluate(model: nn.Module, data: ImageSet, num_classes: int, device: str = "cpu"):
    """(accuracy or None for an empty split, as JSON has no NaN; confusion matrix with rows = true
    zone, columns = predicted; per image, whether it was right), from one pass over the split."""
    m = torch.zeros(num_classes, num_classes, dtype=torch.int64)
    if not len(data):
        return None, m.tolist(), []
    pred = predict(model, data.images, device).argmax(1)
    for t, p in zip(data.labels.tolist(), pred.tolist()):
        m[t, p] += 1
    right = pred == data.labels
    return right.float().mean().item(), m.tolist(), right.tolist()


def accuracy(model: nn.Module, data: ImageSet, device: str = "cpu"):
    """Fraction right, or None for an empty split (JSON has no NaN)."""
    return _evaluate(model, data, device)[1] if len(data) else None
