import pytest
import torch

from krp_training import classifier_models


@pytest.mark.parametrize("arch", classifier_models.ARCHITECTURES)
def test_every_architecture_takes_one_channel_and_gives_one_score_per_zone(arch):
    model = classifier_models.build(arch, num_classes=3).eval()
    with torch.no_grad():
        out = model(torch.zeros(2, 1, 160, 160))
    assert out.shape == (2, 3)


def test_unknown_architecture_is_named_in_the_error():
    with pytest.raises(ValueError, match="resnet"):
        classifier_models.build("resnet", 2)


def test_normalize_maps_the_three_grey_levels_to_minus_one_zero_one():
    x = classifier_models.normalize(torch.tensor([0, 128, 255], dtype=torch.uint8))
    assert torch.allclose(x, torch.tensor([-1.0, 0.0039, 1.0]), atol=1e-3)


def test_compact_refuses_an_image_side_it_cannot_grid():
    with pytest.raises(ValueError, match="multiple of 32"):
        classifier_models.build("compact", 2, input_px=150)


def test_an_architecture_list_names_what_it_does_not_know():
    from krp_training.classifier_models import parse_list
    assert parse_list("compact,,vgg16") == ["compact", "vgg16"]
    with pytest.raises(ValueError, match=r"unknown \['resnet50'\]"):
        parse_list("compact,resnet50")
    with pytest.raises(ValueError, match="none given"):
        parse_list(",")
