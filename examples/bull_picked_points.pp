<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="bull.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-0.349495" y="0.0716853" z="0.308947" active="1" name="nose_tip"/>
 <point x="-0.315994" y="0.0460627" z="0.254743" active="1" name="chin"/>
 <point x="-0.3201" y="0.239168" z="0.251555" active="1" name="head_top"/>
 <point x="-0.252638" y="0.175172" z="0.275579" active="1" name="left_eye"/>
 <point x="-0.384223" y="0.1732" z="0.215981" active="1" name="right_eye"/>
 <point x="-0.117867" y="0.207727" z="0.25778" active="1" name="left_ear_tip"/>
 <point x="-0.465463" y="0.223164" z="0.0974643" active="1" name="right_ear_tip"/>
 <point x="-0.234641" y="0.26722" z="0.400636" active="1" name="left_horn_tip"/>
 <point x="-0.479546" y="0.270453" z="0.28699" active="1" name="right_horn_tip"/>
 <point x="-0.256514" y="0.279646" z="0.151478" active="1" name="neck_top"/>
 <point x="-0.283837" y="0.0109041" z="0.0193136" active="1" name="neck_bottom"/>
 <point x="-0.102939" y="0.198117" z="-0.00275373" active="1" name="withers"/>
 <point x="0.0712039" y="0.144506" z="-0.00691364" active="1" name="mid_back"/>
 <point x="0.262923" y="0.149295" z="0.0234255" active="1" name="rump"/>
 <point x="0.362504" y="0.176615" z="0.0199648" active="1" name="tail_base"/>
 <point x="0.424672" y="0.339538" z="0.250155" active="1" name="tail_tip"/>
 <point x="-0.273821" y="-0.0679575" z="-0.00246689" active="1" name="chest"/>
 <point x="-0.00147752" y="-0.136614" z="0.0295128" active="1" name="belly"/>
 <point x="0.110768" y="-0.0233743" z="0.0950447" active="1" name="left_flank"/>
 <point x="0.135903" y="-0.0263672" z="-0.154135" active="1" name="right_flank"/>
 <point x="-0.332227" y="-0.224636" z="-0.017245" active="1" name="left_front_knee"/>
 <point x="-0.258701" y="-0.191037" z="-0.286109" active="1" name="right_front_knee"/>
 <point x="0.447543" y="-0.207309" z="0.0830779" active="1" name="left_hind_knee"/>
 <point x="0.353563" y="-0.168054" z="-0.164462" active="1" name="right_hind_knee"/>
 <point x="-0.446392" y="-0.322176" z="-0.0852744" active="1" name="left_front_hoof"/>
 <point x="-0.290207" y="-0.294278" z="-0.375003" active="1" name="right_front_hoof"/>
 <point x="0.313615" y="-0.339788" z="0.137672" active="1" name="left_hind_hoof"/>
 <point x="0.183104" y="-0.291924" z="-0.239306" active="1" name="right_hind_hoof"/>
</PickedPoints>
