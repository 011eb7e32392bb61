;R i j k words all missing for arc
g2f1x1
