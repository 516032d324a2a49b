# make bounce-growth: Q16.16 and float error against double per bounce depth
# on the parallel-mirror stress scene (docs/ACCURACY.md "Secondary rays").
bounce-growth: $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) FXRT=$(BUILD)/fxrt bash tests/bounce_growth.sh
.PHONY: bounce-growth

# make adaptive-error: samples 4 adaptive against full 4 x 4 (docs/ACCURACY.md
# "Supersampling").
adaptive-error: $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) FXRT=$(BUILD)/fxrt bash tests/adaptive_error.sh
.PHONY: adaptive-error
