import pytest
import torch

from krp_training.augment import UNKNOWN_GREY, AugmentParams, augment_batch


def _image():
    img = torch.full((1, 1, 32, 32), UNKNOWN_GREY, dtype=torch.uint8)
    img[0, 0, 10:20, 12:16] = 255
    img[0, 0, 10, 12:16] = 0
    return img


def test_no_rotation_no_shift_is_identity():
    img = _image()
    out = augment_batch(img, AugmentParams(max_rotation_deg=0, max_shift_px=0), torch.Generator().manual_seed(0))
    assert torch.equal(out, img)


def test_rotation_keeps_grey_levels_and_fills_with_unknown():
    img = _image()
    out = augment_batch(img.repeat(8, 1, 1, 1), AugmentParams(max_rotation_deg=180, max_shift_px=4),
                        torch.Generator().manual_seed(1))
    assert set(out.unique().tolist()) <= {0, UNKNOWN_GREY, 255}
    assert not torch.equal(out[0], img[0])  # something moved
    # corners are outside the rotated content: unknown
    assert int(out[:, 0, 0, 0].min()) == UNKNOWN_GREY


def test_training_rotation_follows_the_dataset_orientation():
    from krp_training.augment import max_rotation_deg
    assert max_rotation_deg({"submap": {"orientation": "heading_up"}}) == 180.0
    assert max_rotation_deg({"submap": {"orientation": "wall_axes"}}) < 10.0
    assert max_rotation_deg({"submap": {}}) == 180.0  # cards from before orientations existed
    with pytest.raises(ValueError, match="north_up"):
        max_rotation_deg({"submap": {"orientation": "north_up"}})
