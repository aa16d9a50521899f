// The corners of the segmented square-cup holder (holder-segment.geo).
part = 1;
Include "holder-segment.geo";
