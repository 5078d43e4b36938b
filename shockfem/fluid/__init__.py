"""Liquid-filled cavities (the fluid dashpot): a lumped control volume on the bodies' surfaces."""
