<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="man.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="-0.0286574" y="-0.0257813" z="0.5" active="1" name="head_top"/>
 <point x="-0.0299138" y="-0.0874233" z="0.401963" active="1" name="nose_tip"/>
 <point x="-0.0263489" y="-0.0661836" z="0.36195" active="1" name="chin"/>
 <point x="0.0245658" y="-0.00880338" z="0.436881" active="1" name="left_ear"/>
 <point x="-0.0787105" y="-0.00358601" z="0.435913" active="1" name="right_ear"/>
 <point x="0.055904" y="-0.0150893" z="0.344159" active="1" name="left_shoulder"/>
 <point x="-0.109793" y="0.0327736" z="0.3406" active="1" name="right_shoulder"/>
 <point x="0.131333" y="-0.0482556" z="0.147938" active="1" name="left_elbow"/>
 <point x="-0.166407" y="0.0674699" z="0.144669" active="1" name="right_elbow"/>
 <point x="0.12301" y="-0.0951793" z="0.031294" active="1" name="left_wrist"/>
 <point x="-0.187592" y="0.0421848" z="0.0196805" active="1" name="right_wrist"/>
 <point x="0.119245" y="-0.097221" z="-0.0147762" active="1" name="left_hand_tip"/>
 <point x="-0.192665" y="0.0283689" z="-0.0827722" active="1" name="right_hand_tip"/>
 <point x="-0.0429674" y="-0.0716718" z="0.256119" active="1" name="chest"/>
 <point x="-0.0496875" y="-0.0720108" z="0.111532" active="1" name="navel"/>
 <point x="-0.0112167" y="0.0604653" z="0.25754" active="1" name="upper_back"/>
 <point x="-0.028863" y="0.00140541" z="-0.0314546" active="1" name="crotch"/>
 <point x="0.0593437" y="-0.0604612" z="0.0369456" active="1" name="left_hip"/>
 <point x="-0.104115" y="0.0177667" z="0.0372383" active="1" name="right_hip"/>
 <point x="0.103846" y="-0.0784192" z="-0.220754" active="1" name="left_knee"/>
 <point x="-0.133956" y="0.0344492" z="-0.229335" active="1" name="right_knee"/>
 <point x="0.188439" y="-0.026666" z="-0.488765" active="1" name="left_heel"/>
 <point x="-0.137832" y="0.13855" z="-0.495284" active="1" name="right_heel"/>
 <point x="0.164698" y="-0.145867" z="-0.476184" active="1" name="left_toe"/>
 <point x="-0.203663" y="0.0364107" z="-0.495963" active="1" name="right_toe"/>
</PickedPoints>
