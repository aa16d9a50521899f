// The sides of the segmented square-cup holder (holder-segment.geo).
part = 0;
Include "holder-segment.geo";
