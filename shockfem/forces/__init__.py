"""Force sources: the one protocol of everything that pushes the bodies besides their elements
(contact pairs, discrete springs, liquid cavities, a penetrated target), and their registry."""
