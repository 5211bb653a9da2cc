"""Zone classifier architectures: a compact CNN (the shipped default) and the thesis's torchvision ones.

Every model takes the occupancy image as one channel, 1 x H x W, values normalized by
`normalize` below; the torchvision networks get the channel repeated to three inside the model,
so the exported ONNX has the same single-channel input whatever the architecture.
All torchvision networks are built with weights=None: nothing is downloaded.
"""
import torch
from torch import nn
import torchvision

# vgg16_bn / vgg19_bn are VGG16 / VGG19 with batch normalization after every convolution: trained from
# scratch (weights=None), 13 or 16 plain convolutions without it are known to be hard to get moving,
# and the thesis notes its VGGs needed careful tuning of the learning rate.
ARCHITECTURES = ("compact", "googlenet", "vgg16", "vgg16_bn", "vgg19", "vgg19_bn", "densenet121")

# Occupancy image grey levels are 0 (occupied), 128 (unknown), 255 (free): centre them on 0.
INPUT_MEAN = 0.5
INPUT_STD = 0.5


def normalize(grey_uint8: torch.Tensor) -> torch.Tensor:
    return (grey_uint8.float() / 255.0 - INPUT_MEAN) / INPUT_STD


class CompactNet(nn.Module):
    """Halved input, a strided stem, four conv blocks and a head that keeps the layout: ~0.1 M
    parameters, ~0.03 GMAC at 160 px.

    - The input is averaged to half resolution (0.3 m per pixel at the default submap): rooms and
      doors stay distinct, and every later layer costs a quarter.
    - The head flattens a coarse grid of features instead of averaging them away. Which zone a
      submap shows depends on where its rooms and doors lie around the robot, which a global average
      keeps only indirectly. In one uncommitted development run (office_two_zone, 1,900 training
      images, 20 epochs) this head was ahead on the test split and level on the changed split.
    """

    STRIDE = 32  # input pixels per cell of the head's grid
    HEAD_CHANNELS = 16  # features per grid cell kept for the classifier

    def __init__(self, num_classes: int, input_px: int = 160, width: int = 16, dropout: float = 0.3):
        super().__init__()
        if input_px % self.STRIDE:
            raise ValueError(f"compact classifier: the submap image side ({input_px} px) must be a multiple "
                             f"of {self.STRIDE}")
        chans = [width, 2 * width, 4 * width, 8 * width, 8 * width]
        layers = [nn.AvgPool2d(2), nn.Conv2d(1, chans[0], 5, stride=2, padding=2, bias=False),
                  nn.BatchNorm2d(chans[0]), nn.ReLU(inplace=True)]
        for block, (cin, cout) in enumerate(zip(chans[:-1], chans[1:])):
            layers += [nn.Conv2d(cin, cout, 3, padding=1, bias=False), nn.BatchNorm2d(cout), nn.ReLU(inplace=True)]
            if block < len(chans) - 2:
                layers.append(nn.MaxPool2d(2))
        self.features = nn.Sequential(*layers)
        cells = (input_px // self.STRIDE) ** 2
        self.head = nn.Sequential(nn.Conv2d(chans[-1], self.HEAD_CHANNELS, 1), nn.ReLU(inplace=True), nn.Flatten(),
                                  nn.Dropout(dropout), nn.Linear(self.HEAD_CHANNELS * cells, num_classes))

    def forward(self, x):
        return self.head(self.features(x))


class GreyToRgb(nn.Module):
    """Repeats the single input channel so that a three-channel torchvision network accepts it."""

    def __init__(self, net: nn.Module):
        super().__init__()
        self.net = net

    def forward(self, x):
        return self.net(x.expand(-1, 3, -1, -1))


def _vgg(builder, num_classes: int, dropout: float) -> nn.Module:
    net = builder(weights=None)
    # A global-pool head: the 7x7 adaptive pool of the ImageNet head does not export at 160 px,
    # and 100 M head parameters would only memorize a few hundred submaps.
    net.avgpool = nn.AdaptiveAvgPool2d(1)
    net.classifier = nn.Sequential(nn.Flatten(), nn.Dropout(dropout), nn.Linear(512, num_classes))
    return GreyToRgb(net)


def parse_list(text: str) -> list:
    """A comma-separated list of architectures; ValueError naming the unknown ones (or none given)."""
    archs = [a for a in text.split(",") if a]
    unknown = [a for a in archs if a not in ARCHITECTURES]
    if unknown or not archs:
        raise ValueError(f"unknown {unknown or 'none given'}; choose from {', '.join(ARCHITECTURES)}")
    return archs


def build(architecture: str, num_classes: int, dropout: float = 0.3, input_px: int = 160) -> nn.Module:
    if architecture == "compact":
        return CompactNet(num_classes, input_px=input_px, dropout=dropout)
    if architecture == "googlenet":
        net = torchvision.models.googlenet(weights=None, aux_logits=False, init_weights=True,
                                           num_classes=num_classes, dropout=dropout)
        return GreyToRgb(net)
    if architecture == "vgg16":
        return _vgg(torchvision.models.vgg16, num_classes, dropout)
    if architecture == "vgg19":
        return _vgg(torchvision.models.vgg19, num_classes, dropout)
    if architecture == "vgg16_bn":
        return _vgg(torchvision.models.vgg16_bn, num_classes, dropout)
    if architecture == "vgg19_bn":
        return _vgg(torchvision.models.vgg19_bn, num_classes, dropout)
    if architecture == "densenet121":
        net = torchvision.models.densenet121(weights=None, num_classes=num_classes, drop_rate=dropout)
        return GreyToRgb(net)
    raise ValueError(f"unknown architecture '{architecture}'; choose one of {', '.join(ARCHITECTURES)}")
